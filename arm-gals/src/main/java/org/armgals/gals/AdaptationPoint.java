package org.armgals.gals;

/**
 * Where in a cycle an island applies the adaptation requests that wait for it (paper §5.4: "at the
 * beginning or at the end of a cycle"). Either way the entities are quiescent: adaptation runs
 * between two instants, never while an entity reacts.
 */
public enum AdaptationPoint {
  /**
   * Right after the release, before the entities react: a request made before instant {@code k}
   * already shapes the reactions of {@code k}. Adaptation goes first; its time delays the reactions
   * (priority to adaptation).
   */
  BEGIN_OF_CYCLE,

  /**
   * After every entity has reacted: a request made before instant {@code k} shapes the reactions
   * from {@code k + 1}, and adaptation uses the slack left before the next release (priority to the
   * deadline).
   */
  END_OF_CYCLE
}

package org.armgals.kernel;

/**
 * When an entity applies the adaptation requests it receives (paper §5.4): on arrival, or, for a
 * reactive (synchronous) entity, at a renewal point of its cycle.
 */
public enum AdaptationPoint {
  /** As soon as the request is processed, like any other event. */
  ON_ARRIVAL,
  /**
   * Before the first event of the next instant (or, if none comes, at that instant's end): a
   * synchronous entity only.
   */
  BEGIN_OF_CYCLE,
  /** After the events of the instant the request arrived in: a synchronous entity only. */
  END_OF_CYCLE
}

package org.armgals.examples.sim;

/**
 * Where a crew tells what its meta level did: each adaptation goes into the trace (as a note of the
 * cycle), onto the adaptations' time line, and into the run's summary. Called on the thread that
 * runs the simulation, from within a controller or between cycles.
 */
public interface Journal {

  /**
   * Tells that the meta level adapted atom {@code atom}'s robot.
   *
   * @param what the adaptation, short: {@code "added schema climb"}
   * @param why what the meta level saw: {@code "no progress for 2.0 s"}
   */
  void adaptation(int atom, String what, String why);

  /** Tells something else worth keeping in the trace about atom {@code atom}. */
  void note(int atom, String text);
}

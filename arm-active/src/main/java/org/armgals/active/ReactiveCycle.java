package org.armgals.active;

/**
 * A servant of a {@link Mode#SYNCHRONOUS synchronous} object that also does work once per instant:
 * {@link #onCycle} is called at each release of the object's clock, after the events of that
 * instant have been processed, on the object's own thread.
 */
@FunctionalInterface
public interface ReactiveCycle {

  /**
   * One synchronous reaction.
   *
   * @param instant the clock's instant number, starting at 1 for the first release
   * @throws Exception any failure; it is reported like a failed event and the object keeps its
   *     place on the clock
   */
  void onCycle(long instant) throws Exception;
}

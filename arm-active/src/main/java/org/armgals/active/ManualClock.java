package org.armgals.active;

import java.util.function.BooleanSupplier;

/**
 * A clock stepped by hand (style rule: time is injected; Pekko's {@code ManualTime}). Each step is
 * one instant: it releases every registered object and returns once all have finished their cycle,
 * so a sequence of steps with the same inputs gives the same per-instant trace whatever the number
 * of worker threads.
 *
 * <p>Threading: one thread steps at a time; {@link #step} must not be called from inside an object
 * released by this clock.
 */
public sealed interface ManualClock extends Clock permits ManualClockImpl {

  /** Releases one instant and waits until every object finished it; returns its number. */
  long step();

  /**
   * Adds {@code gate}, called by every later {@link #step()} on the stepping thread with the
   * instant about to be released, before the release: the step waits for it to return. A reactive
   * entity in lock step with its meta (virtual time) waits there for the meta's answers, so that
   * the instant starts with them, whatever the threads. A gate must not step this clock; an
   * exception it throws is thrown by the step, before the release. Gates run in the order they were
   * added.
   *
   * @return a handle that removes the gate when closed
   */
  AutoCloseable addReleaseGate(java.util.function.LongConsumer gate);

  /**
   * Releases {@code instants} instants, one after the other, as fast as possible.
   *
   * @throws IllegalArgumentException {@code instants} is negative
   */
  void step(long instants);

  /**
   * Steps until {@code condition} holds after an instant, at most {@code maxInstants} instants.
   *
   * @return whether the condition held
   */
  boolean stepUntil(BooleanSupplier condition, long maxInstants);
}

package org.armgals.active.spi;

import java.time.Duration;

/**
 * How a thread that found no work waits before it looks again, modelled on Agrona's {@code
 * IdleStrategy}: a loop does some work, then calls {@link #idle(int)} with how much it did.
 *
 * <pre>{@code
 * while (running) {
 *   idle.idle(doWork()); // work done: reset; none: one more step of waiting
 * }
 * }</pre>
 *
 * <p>A strategy keeps the state of one waiting thread (how long it has been idle): one instance per
 * thread, not shared. An interrupt does not end a step of waiting early on purpose, and it is left
 * set for the caller to see.
 *
 * <p>Waiting for a point in time rather than for work is {@link DeadlinePacer}'s job.
 */
public interface IdleStrategy {

  /**
   * One step of the loop: after work ({@code workCount > 0}) it {@linkplain #reset() resets} and
   * returns at once; after none it {@linkplain #idle() idles} one step.
   *
   * @param workCount how much work the loop did since its last call, 0 for none
   */
  default void idle(int workCount) {
    if (workCount > 0) {
      reset();
    } else {
      idle();
    }
  }

  /**
   * One step of waiting; how long it lasts is the strategy's (a backoff waits longer each step).
   */
  void idle();

  /** Work was found: the next {@link #idle()} starts again with the shortest wait. */
  void reset();

  /**
   * Spins {@code maxSpins} steps, then yields {@code maxYields} steps, then parks, first for {@code
   * minPark} and twice as long at each step up to {@code maxPark}. See {@link BackoffIdleStrategy}.
   */
  static BackoffIdleStrategy backoff(
      long maxSpins, long maxYields, Duration minPark, Duration maxPark) {
    return new BackoffIdleStrategy(maxSpins, maxYields, minPark, maxPark);
  }
}

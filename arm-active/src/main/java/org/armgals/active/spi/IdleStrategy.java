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
   * One step of a wait whose caller blocks its own way once spinning is over: a thread that parks
   * until another hands it work, after a handshake with that other thread that a strategy cannot
   * make for it (announce itself, look for work once more, then park). While the strategy would
   * spin (or yield), this does one such step and returns {@code true}: the caller looks for work
   * again. Once the strategy would park, it returns {@code false} at once, without parking, and
   * keeps returning {@code false} until {@link #reset()}: the caller blocks now. A caller that
   * finds work calls {@link #reset()}, so a strategy learns whether its spins find work.
   *
   * <pre>{@code
   * while (strategy.spin()) {
   *   if (tryTakeWork()) { strategy.reset(); return; }
   * }
   * blockUntilHandedWork(); // the caller's own park and handshake
   * strategy.reset();
   * }</pre>
   *
   * @return true to look for work again, false to block now
   */
  boolean spin();

  /**
   * Spins {@code maxSpins} steps, then yields {@code maxYields} steps, then parks, first for {@code
   * minPark} and twice as long at each step up to {@code maxPark}. See {@link BackoffIdleStrategy}.
   */
  static BackoffIdleStrategy backoff(
      long maxSpins, long maxYields, Duration minPark, Duration maxPark) {
    return new BackoffIdleStrategy(maxSpins, maxYields, minPark, maxPark);
  }
}

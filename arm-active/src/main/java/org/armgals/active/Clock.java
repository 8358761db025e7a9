package org.armgals.active;

import java.time.Duration;

/**
 * Rhythms synchronous (reactive) objects (paper §5.3, class {@code Clock}): at each release every
 * object registered on it takes all the events waiting in its buffer at that instant and processes
 * them, then runs its {@link ReactiveCycle} if it has one. An instant ends when every object has
 * finished; what an object emits during instant {@code k} is seen by the others at {@code k + 1}.
 *
 * <p>Objects register by being created with {@link ObjectConfig#synchronous(Clock)}; a stopped
 * object leaves its clock. Two clocks: {@link #manual} (instants stepped by hand or as fast as
 * possible, for tests and simulation; deterministic) and {@link #realTime} (periodic, drift-free).
 * A clock is also the {@link TimeSource} of its objects' world: manual time advances one period per
 * instant.
 */
public sealed interface Clock extends TimeSource, AutoCloseable permits ManualClock, RealTimeClock {

  /**
   * A manual clock whose instants are {@code period} apart in its virtual time.
   *
   * @throws IllegalArgumentException {@code period} is not positive
   */
  static ManualClock manual(Duration period) {
    return new ManualClockImpl(period);
  }

  /**
   * A real-time clock releasing every {@code period}; not started.
   *
   * @throws IllegalArgumentException {@code period} is not positive
   */
  static RealTimeClock realTime(Duration period) {
    return new RealTimeClockImpl(period, TimeSource.system());
  }

  /** The time between two releases. */
  Duration period();

  /** The number of the last release, 0 before the first. */
  long instant();

  /** What the clock measured of itself. */
  ClockStats stats();

  /** Stops releasing; waits for the instant in progress to end. Idempotent. */
  @Override
  void close();
}

package org.armgals.maam.sim.spi;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.function.LongConsumer;
import org.armgals.active.TimeSource;
import org.armgals.active.spi.DeadlinePacer;

/**
 * Holds virtual time to real time, or not. The simulation calls {@link #pace} after each control
 * cycle with the virtual time elapsed since its start.
 */
@FunctionalInterface
public interface Pacer {

  /**
   * Returns once real time has caught up with {@code virtualNanos} (or at once, if it does not
   * pace).
   */
  void pace(long virtualNanos);

  /** Never waits: the simulation runs as fast as the machine allows. */
  static Pacer asFastAsPossible() {
    return virtualNanos -> {};
  }

  /** Paces to the machine's monotonic clock, parking the simulating thread. */
  static Pacer realTime() {
    return realTime(1.0);
  }

  /**
   * Paces so that virtual time runs {@code speed} times as fast as the machine's monotonic clock,
   * parking the simulating thread (no spinning: a simulation step is not a hard real-time release).
   */
  static Pacer realTime(double speed) {
    return realTime(DeadlinePacer.of(TimeSource.system(), Duration.ZERO), speed);
  }

  /**
   * Paces so that virtual time runs {@code speed} times as fast as {@code time}: after virtual time
   * {@code v}, waits with {@code sleeper} (nanoseconds, called again if it returns early) until
   * {@code time} has advanced by {@code v / speed} since the first call.
   */
  static Pacer realTime(TimeSource time, LongConsumer sleeper, double speed) {
    return realTime(DeadlinePacer.of(time, Duration.ZERO, sleeper), speed);
  }

  /**
   * Paces so that virtual time runs {@code speed} times as fast as {@code pacer}'s time: after
   * virtual time {@code v}, waits with {@code pacer} until its time has advanced by {@code v /
   * speed} since the first call.
   */
  static Pacer realTime(DeadlinePacer pacer, double speed) {
    requireNonNull(pacer, "pacer");
    if (!(speed > 0) || Double.isInfinite(speed)) {
      throw new IllegalArgumentException("pacing speed " + speed + " is not a finite number > 0");
    }
    return new RealTimePacer(pacer, speed);
  }
}

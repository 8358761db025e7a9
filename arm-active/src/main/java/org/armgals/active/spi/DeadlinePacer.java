package org.armgals.active.spi;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import java.util.function.LongConsumer;
import org.armgals.active.TimeSource;
import org.jspecify.annotations.Nullable;

/**
 * Waits until a point in time of a {@link TimeSource}: parks until a spin margin before it, then
 * spins the rest, because parking alone wakes tens of microseconds late (too coarse for a 1 kHz
 * release). The one way the runtime's real-time clocks, the islands' real-time runners and the
 * simulator's pacer wait for a release.
 *
 * <p>The contract: {@link #awaitUntil(long, BooleanSupplier)} returns {@code true} only once the
 * time source has reached the deadline, never before, however early a park returns (a park may
 * return early or spuriously: the pacer reads the time again and waits the rest). It returns {@code
 * false} as soon as it sees its stop condition hold, which it checks before each park or spin. An
 * interrupt does not end the wait (stop does), and is left set.
 *
 * <p>A pacer keeps no state between waits: one may be shared by threads.
 */
public final class DeadlinePacer {

  /** The default spin margin, 100 µs: more than a park's usual lateness on a virtual machine. */
  public static final Duration DEFAULT_SPIN = Duration.ofNanos(100_000);

  private static final BooleanSupplier NEVER = () -> false;

  private final TimeSource time;
  private final long spinNanos;

  /**
   * Parks for the nanoseconds it is given: {@link LockSupport#parkNanos} unless a test gave one.
   */
  private final LongConsumer parker;

  private DeadlinePacer(TimeSource time, Duration spin, @Nullable LongConsumer parker) {
    this.time = requireNonNull(time, "time");
    requireNonNull(spin, "spin");
    if (spin.isNegative()) {
      throw new IllegalArgumentException("spin margin must be >= 0, was " + spin);
    }
    this.spinNanos = spin.toNanos();
    this.parker = parker != null ? parker : nanos -> LockSupport.parkNanos(this, nanos);
  }

  /** A pacer on {@code time} that parks until {@link #DEFAULT_SPIN} before a deadline. */
  public static DeadlinePacer of(TimeSource time) {
    return new DeadlinePacer(time, DEFAULT_SPIN, null);
  }

  /**
   * A pacer on {@code time} that parks until {@code spin} before a deadline and spins the rest;
   * {@link Duration#ZERO} parks only (cheaper, less exact).
   */
  public static DeadlinePacer of(TimeSource time, Duration spin) {
    return new DeadlinePacer(time, spin, null);
  }

  /**
   * As {@link #of(TimeSource, Duration)}, parking with {@code parker} (given nanoseconds): a test
   * passes one that moves a fake time instead of waiting.
   */
  public static DeadlinePacer of(TimeSource time, Duration spin, LongConsumer parker) {
    return new DeadlinePacer(time, spin, requireNonNull(parker, "parker"));
  }

  /** The time source the deadlines are on. */
  public TimeSource time() {
    return time;
  }

  /** The spin margin before a deadline. */
  public Duration spin() {
    return Duration.ofNanos(spinNanos);
  }

  /**
   * Returns once {@link #time()} has reached {@code due} (nanoseconds on it), or early when {@code
   * stop} holds.
   *
   * @return true if the deadline was reached, false if the wait stopped before
   */
  public boolean awaitUntil(long due, BooleanSupplier stop) {
    for (; ; ) {
      long remaining = due - time.nanoTime();
      if (remaining <= 0) {
        return true;
      }
      if (stop.getAsBoolean()) {
        return false;
      }
      if (remaining > spinNanos) {
        park(remaining - spinNanos);
      } else {
        Thread.onSpinWait();
      }
    }
  }

  /** Returns once {@link #time()} has reached {@code due}. */
  public void awaitUntil(long due) {
    awaitUntil(due, NEVER);
  }

  private void park(long nanos) {
    parker.accept(nanos);
  }

  @Override
  public String toString() {
    return "DeadlinePacer[spin=" + spin() + "]";
  }
}

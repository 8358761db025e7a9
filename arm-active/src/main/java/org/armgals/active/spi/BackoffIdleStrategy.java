package org.armgals.active.spi;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.concurrent.locks.LockSupport;
import java.util.function.LongConsumer;
import org.jspecify.annotations.Nullable;

/**
 * An {@link IdleStrategy} that backs off in phases: it spins ({@link Thread#onSpinWait()}) for a
 * number of steps, then yields ({@link Thread#yield()}) for a number of steps, then parks, first
 * for the shortest park and twice as long at each step up to the longest. A {@link #reset()} starts
 * again from the spinning phase. A phase of zero steps is skipped, so that {@code (0, 0, p, p)}
 * parks {@code p} at every step.
 *
 * <p>One instance per waiting thread (its state is the thread's).
 */
public final class BackoffIdleStrategy implements IdleStrategy {

  /** Where a strategy is: the phase of its next step. */
  public enum Phase {
    /** Reset: the next step starts spinning (or the first phase that has steps). */
    NOT_IDLE,
    /** Spinning, with steps of that phase left. */
    SPINNING,
    /** Yielding, with steps of that phase left. */
    YIELDING,
    /** Parking: every further step parks, for {@link #nextParkNanos()}. */
    PARKING
  }

  private final long maxSpins;
  private final long maxYields;
  private final long minParkNanos;
  private final long maxParkNanos;

  /**
   * Parks for the nanoseconds it is given: {@link LockSupport#parkNanos} unless a test gave one.
   */
  private final LongConsumer parker;

  private Phase phase = Phase.NOT_IDLE;
  private long steps;
  private long parkNanos;

  /**
   * A strategy that parks the calling thread with {@link LockSupport#parkNanos(Object, long)}.
   *
   * @param maxSpins spinning steps, {@code >= 0}
   * @param maxYields yielding steps, {@code >= 0}
   * @param minPark the first park, {@code > 0}
   * @param maxPark the longest park, {@code >= minPark}
   */
  public BackoffIdleStrategy(long maxSpins, long maxYields, Duration minPark, Duration maxPark) {
    this(null, maxSpins, maxYields, minPark, maxPark);
  }

  /**
   * A strategy that parks with {@code parker} (given nanoseconds): tests pass one that records the
   * parks or moves a fake time instead of waiting.
   */
  public BackoffIdleStrategy(
      long maxSpins, long maxYields, Duration minPark, Duration maxPark, LongConsumer parker) {
    this(requireNonNull(parker, "parker"), maxSpins, maxYields, minPark, maxPark);
  }

  private BackoffIdleStrategy(
      @Nullable LongConsumer parker,
      long maxSpins,
      long maxYields,
      Duration minPark,
      Duration maxPark) {
    requireNonNull(minPark, "minPark");
    requireNonNull(maxPark, "maxPark");
    if (maxSpins < 0) {
      throw new IllegalArgumentException("maxSpins must be >= 0, was " + maxSpins);
    }
    if (maxYields < 0) {
      throw new IllegalArgumentException("maxYields must be >= 0, was " + maxYields);
    }
    if (minPark.isNegative() || minPark.isZero()) {
      throw new IllegalArgumentException("minPark must be > 0, was " + minPark);
    }
    if (maxPark.compareTo(minPark) < 0) {
      throw new IllegalArgumentException(
          "maxPark must be >= minPark (" + minPark + "), was " + maxPark);
    }
    this.maxSpins = maxSpins;
    this.maxYields = maxYields;
    this.minParkNanos = saturatedNanos(minPark);
    this.maxParkNanos = saturatedNanos(maxPark);
    this.parker = parker != null ? parker : nanos -> LockSupport.parkNanos(this, nanos);
    this.parkNanos = minParkNanos;
  }

  @Override
  public void idle() {
    if (spin()) {
      return;
    }
    long nanos = parkNanos;
    parkNanos = nanos <= maxParkNanos / 2 ? nanos * 2 : maxParkNanos;
    park(nanos);
  }

  /** A step of spinning or yielding while either phase has steps left; false once it would park. */
  @Override
  public boolean spin() {
    if (phase == Phase.NOT_IDLE) {
      phase = Phase.SPINNING;
      steps = 0;
    }
    if (phase == Phase.SPINNING) {
      if (steps < maxSpins) {
        steps++;
        Thread.onSpinWait();
        return true;
      }
      phase = Phase.YIELDING;
      steps = 0;
    }
    if (phase == Phase.YIELDING) {
      if (steps < maxYields) {
        steps++;
        Thread.yield();
        return true;
      }
      phase = Phase.PARKING;
      parkNanos = minParkNanos;
    }
    return false;
  }

  private void park(long nanos) {
    parker.accept(nanos);
  }

  @Override
  public void reset() {
    phase = Phase.NOT_IDLE;
    steps = 0;
    parkNanos = minParkNanos;
  }

  /** The phase of the next step. */
  public Phase phase() {
    return phase;
  }

  /** How long the next park lasts, in nanoseconds (the shortest park until parking begins). */
  public long nextParkNanos() {
    return parkNanos;
  }

  private static long saturatedNanos(Duration d) {
    try {
      return d.toNanos();
    } catch (ArithmeticException e) {
      return Long.MAX_VALUE;
    }
  }

  @Override
  public String toString() {
    return "BackoffIdleStrategy[spins="
        + maxSpins
        + ", yields="
        + maxYields
        + ", park="
        + Duration.ofNanos(minParkNanos)
        + ".."
        + Duration.ofNanos(maxParkNanos)
        + ", phase="
        + phase
        + "]";
  }
}

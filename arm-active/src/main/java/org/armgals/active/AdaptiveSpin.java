package org.armgals.active;

import java.util.concurrent.locks.LockSupport;
import java.util.function.LongConsumer;
import org.armgals.active.spi.IdleStrategy;

/**
 * The dispatcher's {@link IdleStrategy}: how an idle worker spins on the run queue before it parks
 * in the idle list (decisions 0002, 0033, 0072). Each wait spins for a time of its own, between a
 * shortest and a longest spin:
 *
 * <ul>
 *   <li>a wait whose spin found work ({@link #reset()} while spinning) doubles the next spin, a
 *       spin that ran out halves it: a worker that has nothing to do stops taking the core from the
 *       threads that do (on a small machine, an outside sender is one of them);
 *   <li>{@link #blockedFor(long)}: work that came soon after the caller blocked, on a path where a
 *       wake-up costs a round trip, makes the next spin twice the last one that ran out (decision
 *       0033: a worker learns the pace of requests from another runtime).
 * </ul>
 *
 * <p>Each {@link #spin()} is one step of the spin and reads the clock once: its caller looks for
 * work several times per step, pausing with {@link Thread#onSpinWait()} between looks (the
 * dispatcher makes {@link Dispatcher#SPIN_BATCH} looks), so that its loop keeps its counter in a
 * register and the clock is read once per batch. {@link #late()} says whether that reading was in
 * the spin's last quarter. The caller blocks its own way once {@link #spin()} returns false (the
 * dispatcher's idle list, after its handshake with producers); {@link #idle()} parks, for a caller
 * with no way of its own: from 1 µs, doubling, up to the longest spin. One instance per waiting
 * thread; not thread-safe.
 */
final class AdaptiveSpin extends AdaptiveSpinPadding implements IdleStrategy {

  private static final long MIN_PARK_NANOS = 1_000;

  private enum State {
    /** Between waits. */
    NOT_IDLE,
    /** Spinning, until {@link #end}. */
    SPINNING,
    /** The spin ran out: the caller blocks. */
    RAN_OUT
  }

  private final TimeSource time;
  private final long minSpinNanos;
  private final long maxSpinNanos;
  private final LongConsumer parker;

  private State state = State.NOT_IDLE;

  /** The length of the next spin. */
  private long spinNanos;

  /** The length of the current, or last, spin. */
  private long budget;

  /** The length of the last spin that ran out. */
  private long lastFailedSpin;

  private long end;
  private boolean late;
  private long parkNanos = MIN_PARK_NANOS;

  /**
   * @param time the time spins are measured on
   * @param minSpinNanos the shortest spin, {@code > 0}
   * @param maxSpinNanos the longest spin, {@code >= minSpinNanos}
   * @param firstSpinNanos the first spin, clamped between them
   * @param parker parks for the nanoseconds it is given ({@link #idle()} only)
   */
  AdaptiveSpin(
      TimeSource time,
      long minSpinNanos,
      long maxSpinNanos,
      long firstSpinNanos,
      LongConsumer parker) {
    if (minSpinNanos <= 0 || maxSpinNanos < minSpinNanos) {
      throw new IllegalArgumentException(
          "spins must be 0 < min <= max, were " + minSpinNanos + " and " + maxSpinNanos);
    }
    this.time = time;
    this.minSpinNanos = minSpinNanos;
    this.maxSpinNanos = maxSpinNanos;
    this.spinNanos = Math.clamp(firstSpinNanos, minSpinNanos, maxSpinNanos);
    this.lastFailedSpin = minSpinNanos;
    this.parker = parker;
  }

  /** Parks with {@link LockSupport#parkNanos(Object, long)}. */
  AdaptiveSpin(TimeSource time, long minSpinNanos, long maxSpinNanos, long firstSpinNanos) {
    this(
        time,
        minSpinNanos,
        maxSpinNanos,
        firstSpinNanos,
        nanos -> LockSupport.parkNanos(AdaptiveSpin.class, nanos));
  }

  @Override
  public boolean spin() {
    State s = state;
    if (s == State.SPINNING) {
      long left = end - time.nanoTime();
      if (left > 0) {
        late = left <= budget >> 2;
        return true;
      }
      state = State.RAN_OUT;
      spinNanos = Math.max(minSpinNanos, budget >> 1);
      lastFailedSpin = budget;
      return false;
    }
    if (s != State.NOT_IDLE) {
      return false;
    }
    budget = spinNanos;
    end = time.nanoTime() + budget;
    late = false;
    state = State.SPINNING;
    return true;
  }

  /** Whether the spin was in its last quarter at the last reading of the clock. */
  boolean late() {
    return late;
  }

  @Override
  public void idle() {
    if (spin()) {
      Thread.onSpinWait();
      return;
    }
    long nanos = parkNanos;
    parkNanos = Math.min(maxSpinNanos, nanos << 1);
    parker.accept(nanos);
  }

  /** Ends the wait: work was found. If it was found while spinning, the next spin is longer. */
  @Override
  public void reset() {
    if (state == State.SPINNING) {
      spinNanos = Math.min(maxSpinNanos, budget << 1);
    }
    state = State.NOT_IDLE;
    parkNanos = MIN_PARK_NANOS;
  }

  /**
   * Ends a wait that blocked, given work {@code blockedNanos} after it blocked: if that is within
   * the longest spin, the next spin is twice the last one that ran out (decision 0033).
   */
  void blockedFor(long blockedNanos) {
    if (blockedNanos >= 0 && blockedNanos < maxSpinNanos) {
      spinNanos = Math.min(maxSpinNanos, lastFailedSpin << 1);
    }
    reset();
  }

  /** The length of the next spin (tests). */
  long spinNanos() {
    return spinNanos;
  }
}

package org.armgals.active;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import org.armgals.active.spi.ObjectListener;
import org.jspecify.annotations.Nullable;

/**
 * How an active object is made: its mode, its clock (synchronous mode only), the capacity of its
 * bounded buffer, what happens when the buffer is full, and who hears about its drops and failures.
 * Validated when built; immutable; one instance can serve many objects.
 *
 * @param mode asynchronous or synchronous
 * @param clock the clock that releases a synchronous object; {@code null} for an asynchronous one
 * @param capacity the most events the buffer holds, at least 1
 * @param overflow what to do with an event that finds the buffer full
 * @param listener told of every drop and failure of the object
 */
public record ObjectConfig(
    Mode mode,
    @Nullable Clock clock,
    int capacity,
    OverflowPolicy overflow,
    ObjectListener listener) {

  /** The capacity of a buffer when none is given. */
  public static final int DEFAULT_CAPACITY = 1 << 16;

  /** How long a sender waits for room by default (asynchronous objects). */
  public static final Duration DEFAULT_BLOCK_TIMEOUT = Duration.ofSeconds(10);

  /** Checks the configuration as a whole. */
  public ObjectConfig {
    requireNonNull(mode, "mode");
    requireNonNull(overflow, "overflow");
    requireNonNull(listener, "listener");
    if (capacity < 1) {
      throw new IllegalArgumentException("capacity must be >= 1, was " + capacity);
    }
    if (mode == Mode.SYNCHRONOUS && clock == null) {
      throw new IllegalArgumentException("a SYNCHRONOUS object needs a clock, was null");
    }
    if (mode == Mode.ASYNCHRONOUS && clock != null) {
      throw new IllegalArgumentException(
          "an ASYNCHRONOUS object takes no clock, was " + clock + "; use ObjectConfig.synchronous");
    }
    if (mode == Mode.SYNCHRONOUS && overflow instanceof OverflowPolicy.Block) {
      throw new IllegalArgumentException(
          "overflow policy "
              + overflow
              + " is not allowed for a SYNCHRONOUS object (a reactive object never blocks its"
              + " sender); expected reject, drop-newest or drop-oldest");
    }
  }

  /**
   * An asynchronous object with a buffer of {@link #DEFAULT_CAPACITY} that blocks its senders up to
   * {@link #DEFAULT_BLOCK_TIMEOUT} when full.
   */
  public static ObjectConfig asynchronous() {
    return DEFAULT_ASYNCHRONOUS;
  }

  /** Shared: a configuration is an immutable value, and one per object would cost 48 bytes. */
  private static final ObjectConfig DEFAULT_ASYNCHRONOUS =
      new ObjectConfig(
          Mode.ASYNCHRONOUS,
          null,
          DEFAULT_CAPACITY,
          OverflowPolicy.block(DEFAULT_BLOCK_TIMEOUT),
          ObjectListener.NONE);

  /**
   * A synchronous (reactive) object released by {@code clock}, with a buffer of {@link
   * #DEFAULT_CAPACITY} that drops its oldest event when full (the newest data is worth more to a
   * reactive object than the oldest).
   */
  public static ObjectConfig synchronous(Clock clock) {
    requireNonNull(clock, "clock");
    return new ObjectConfig(
        Mode.SYNCHRONOUS,
        clock,
        DEFAULT_CAPACITY,
        OverflowPolicy.dropOldest(),
        ObjectListener.NONE);
  }

  /** This configuration with another buffer capacity. */
  public ObjectConfig withCapacity(int capacity) {
    return new ObjectConfig(mode, clock, capacity, overflow, listener);
  }

  /** This configuration with another overflow policy. */
  public ObjectConfig withOverflow(OverflowPolicy overflow) {
    return new ObjectConfig(mode, clock, capacity, overflow, listener);
  }

  /** This configuration with another listener. */
  public ObjectConfig withListener(ObjectListener listener) {
    return new ObjectConfig(mode, clock, capacity, overflow, listener);
  }
}

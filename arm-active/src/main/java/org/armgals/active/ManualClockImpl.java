package org.armgals.active;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.BooleanSupplier;

/** The manual clock: instants stepped by the caller's thread; virtual time = instants × period. */
final class ManualClockImpl implements ManualClock, ClockSupport.Owner {
  private final ClockSupport support;
  private final Duration period;
  private final long periodNanos;
  private final ReentrantLock stepping = new ReentrantLock();
  private volatile long instant;
  private volatile boolean closed;
  private final java.util.List<java.util.function.LongConsumer> gates =
      new java.util.concurrent.CopyOnWriteArrayList<>();

  ManualClockImpl(Duration period) {
    this.periodNanos = ClockSupport.positiveNanos(period);
    this.support = new ClockSupport(period);
    this.period = period;
  }

  @Override
  public ClockSupport support() {
    return support;
  }

  @Override
  public AutoCloseable addReleaseGate(java.util.function.LongConsumer gate) {
    java.util.Objects.requireNonNull(gate, "gate");
    gates.add(gate);
    return () -> gates.remove(gate);
  }

  @Override
  public long step() {
    if (Core.current() != null) {
      Core<?> c = Core.current();
      if (c != null && c.config().clock() == this) {
        throw new IllegalStateException(
            "object " + c.address() + " cannot step the clock that releases it");
      }
    }
    stepping.lock();
    try {
      if (closed) {
        throw new IllegalStateException("manual clock is closed");
      }
      long k = instant + 1;
      for (java.util.function.LongConsumer gate : gates) {
        gate.accept(k);
      }
      instant = k;
      support.release(k);
      support.record(k * periodNanos, 0, 0);
      return k;
    } finally {
      stepping.unlock();
    }
  }

  @Override
  public void step(long instants) {
    if (instants < 0) {
      throw new IllegalArgumentException("instants must be >= 0, was " + instants);
    }
    for (long i = 0; i < instants; i++) {
      step();
    }
  }

  @Override
  public boolean stepUntil(BooleanSupplier condition, long maxInstants) {
    requireNonNull(condition, "condition");
    if (maxInstants < 0) {
      throw new IllegalArgumentException("maxInstants must be >= 0, was " + maxInstants);
    }
    for (long i = 0; i < maxInstants; i++) {
      step();
      if (condition.getAsBoolean()) {
        return true;
      }
    }
    return condition.getAsBoolean();
  }

  @Override
  public Duration period() {
    return period;
  }

  @Override
  public long instant() {
    return instant;
  }

  @Override
  public long nanoTime() {
    return instant * periodNanos;
  }

  @Override
  public ClockStats stats() {
    return support.stats();
  }

  @Override
  public void close() {
    stepping.lock();
    try {
      closed = true;
    } finally {
      stepping.unlock();
    }
  }

  @Override
  public String toString() {
    return "ManualClock[period=" + period + ", instant=" + instant + "]";
  }
}

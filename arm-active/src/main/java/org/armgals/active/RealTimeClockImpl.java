package org.armgals.active;

import java.time.Duration;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import org.armgals.active.spi.DeadlinePacer;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The real-time clock: release {@code k} is due at {@code origin + k × period}. The clock thread
 * waits for it with a {@link DeadlinePacer} (parks until 100 µs before, then spins). An instant
 * still running when the next release is due is an overrun; the missed releases are skipped (not
 * caught up).
 */
final class RealTimeClockImpl implements RealTimeClock, ClockSupport.Owner {
  private static final Logger LOG = LoggerFactory.getLogger(RealTimeClockImpl.class);

  private final ClockSupport support;
  private final Duration period;
  private final long periodNanos;
  private final TimeSource time;
  private final DeadlinePacer pacer;
  private final BooleanSupplier isClosed = () -> this.closed;
  private volatile long instant;
  private volatile long origin;
  private volatile boolean closed;
  private @Nullable Thread thread;

  RealTimeClockImpl(Duration period, TimeSource time) {
    this.periodNanos = ClockSupport.positiveNanos(period);
    this.support = new ClockSupport(period);
    this.period = period;
    this.time = time;
    this.pacer = DeadlinePacer.of(time);
  }

  @Override
  public ClockSupport support() {
    return support;
  }

  @Override
  public synchronized void start() {
    if (closed) {
      throw new IllegalStateException("real-time clock is closed");
    }
    if (thread != null) {
      return;
    }
    origin = time.nanoTime();
    Thread t =
        Thread.ofPlatform().name("armgals-clock-" + period).daemon(true).unstarted(this::run);
    thread = t;
    t.start();
  }

  private void run() {
    long k = 1;
    while (!closed) {
      long due = origin + k * periodNanos;
      pacer.awaitUntil(due, isClosed);
      if (closed) {
        return;
      }
      long released = time.nanoTime();
      instant = k;
      try {
        support.release(k);
      } catch (RuntimeException e) {
        LOG.error("real-time clock {}: instant {} failed", period, k, e);
      }
      long end = time.nanoTime();
      long nextDue = due + periodNanos;
      boolean overrun = end > nextDue;
      support.record(released - origin, released - due, end - released);
      k++;
      if (overrun) {
        k = (end - origin) / periodNanos + 1;
      }
    }
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
    return time.nanoTime() - origin;
  }

  @Override
  public ClockStats stats() {
    return support.stats();
  }

  @Override
  public void close() {
    Thread t;
    synchronized (this) {
      closed = true;
      t = thread;
    }
    if (t != null && t != Thread.currentThread()) {
      LockSupport.unpark(t);
      try {
        t.join();
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
    }
  }

  @Override
  public String toString() {
    return "RealTimeClock[period=" + period + ", instant=" + instant + "]";
  }
}

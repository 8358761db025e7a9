package org.armgals.active;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import org.HdrHistogram.Histogram;

/**
 * What both clocks share: the registered objects, the two-phase release of an instant, and the
 * figures (period, jitter, overruns).
 *
 * <p>A release first fixes, for every object, which events belong to the instant (phase 1), and
 * only then lets them run (phase 2), so nothing emitted during the instant is taken in it. The
 * instant ends when every object has finished.
 */
final class ClockSupport {

  /** Implemented by the clocks, so that objects can find the support of their clock. */
  interface Owner {
    ClockSupport support();
  }

  private final CopyOnWriteArrayList<Core<?>> objects = new CopyOnWriteArrayList<>();
  private final Histogram jitter = new Histogram(Duration.ofSeconds(10).toNanos(), 3);
  private long instants;
  private long overruns;
  private long firstRelease;
  private long lastRelease;
  private long cycleMax;

  void register(Core<?> core) {
    objects.add(core);
  }

  void unregister(Core<?> core) {
    objects.remove(core);
  }

  /** Runs instant {@code k}: releases every object and waits until all have finished. */
  void release(long k) {
    List<Core<?>> snapshot = List.copyOf(objects);
    for (Core<?> c : snapshot) {
      c.beginInstant();
    }
    CountDownLatch done = new CountDownLatch(snapshot.size());
    for (Core<?> c : snapshot) {
      if (!c.scheduleInstant(k, done)) {
        done.countDown();
      }
    }
    boolean interrupted = false;
    Core<?> caller = Core.current();
    if (caller != null) {
      caller.returnTaken(); // stepped from an asynchronous object: its count stays exact
    }
    Dispatcher.beforeBlock(); // ...and the other workers keep going
    try {
      for (; ; ) {
        try {
          done.await();
          break;
        } catch (InterruptedException e) {
          interrupted = true;
        }
      }
    } finally {
      Dispatcher.afterBlock();
    }
    if (interrupted) {
      Thread.currentThread().interrupt();
    }
  }

  /** Records one release: its time, its lateness behind schedule, how long the instant took. */
  synchronized void record(long releasedAt, long lateness, long cycleNanos, boolean overrun) {
    if (instants == 0) {
      firstRelease = releasedAt;
    }
    lastRelease = releasedAt;
    instants++;
    jitter.recordValue(Math.min(Math.max(lateness, 0), jitter.getHighestTrackableValue()));
    cycleMax = Math.max(cycleMax, cycleNanos);
    if (overrun) {
      overruns++;
    }
  }

  synchronized long overruns() {
    return overruns;
  }

  synchronized ClockStats stats() {
    Duration mean =
        instants < 2
            ? Duration.ZERO
            : Duration.ofNanos((lastRelease - firstRelease) / (instants - 1));
    return new ClockStats(
        instants,
        overruns,
        mean,
        Duration.ofNanos(jitter.getValueAtPercentile(50)),
        Duration.ofNanos(jitter.getValueAtPercentile(99)),
        Duration.ofNanos(jitter.getMaxValue()),
        Duration.ofNanos(cycleMax));
  }

  static long positiveNanos(Duration period) {
    java.util.Objects.requireNonNull(period, "period");
    if (period.isNegative() || period.isZero()) {
      throw new IllegalArgumentException("period must be > 0, was " + period);
    }
    return period.toNanos();
  }
}

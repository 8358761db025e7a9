package org.armgals.active;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import org.armgals.active.spi.CycleRecorder;

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
  private final CycleRecorder figures;

  ClockSupport(Duration period) {
    this.figures = new CycleRecorder(period);
  }

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
  void record(long releasedAt, long lateness, long cycleNanos) {
    figures.record(releasedAt, lateness, cycleNanos);
  }

  long overruns() {
    return figures.overruns();
  }

  ClockStats stats() {
    CycleRecorder.Figures f = figures.snapshot();
    return new ClockStats(
        f.instants(),
        f.overruns(),
        f.meanPeriod(),
        f.jitterP50(),
        f.jitterP99(),
        f.jitterMax(),
        f.cycleMax());
  }

  static long positiveNanos(Duration period) {
    java.util.Objects.requireNonNull(period, "period");
    if (period.isNegative() || period.isZero()) {
      throw new IllegalArgumentException("period must be > 0, was " + period);
    }
    return period.toNanos();
  }
}

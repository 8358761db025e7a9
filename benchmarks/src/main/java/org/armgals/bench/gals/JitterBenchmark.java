package org.armgals.bench.gals;

import java.io.PrintStream;
import java.time.Duration;
import java.util.Locale;
import java.util.concurrent.locks.LockSupport;
import org.HdrHistogram.Histogram;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.TimeSource;
import org.armgals.active.spi.DeadlinePacer;
import org.armgals.gals.Island;
import org.armgals.gals.IslandStats;

/**
 * {@code gals name=jitter impl=<armgals|raw> hz=1000 p50_us=<a> p99_us=<b> max_us=<c>}: the
 * lateness of each release behind its schedule at 1 kHz, for an island of 100 reactive entities
 * doing {@link Work#cycle} each, and for a raw loop on one platform thread that parks, spins to the
 * release and does the same work itself. Both run in this JVM, one after the other, each warmed up
 * as long as it is measured.
 */
final class JitterBenchmark {
  static final int ENTITIES = 100;
  static final Duration PERIOD = Duration.ofMillis(1);
  private static final long SPIN_NANOS = 100_000;

  private JitterBenchmark() {}

  /**
   * Prints the two lines. Each measured part runs {@code -Dgals.seconds} seconds (default 5), after
   * a warm-up as long.
   */
  static void run() throws Exception {
    int seconds = Integer.getInteger("gals.seconds", 5);
    if (seconds < 1) {
      throw new IllegalArgumentException("gals.seconds must be >= 1, was " + seconds);
    }
    PrintStream out = System.out;
    Duration length = Duration.ofSeconds(seconds);
    try (ActiveRuntime runtime =
        ActiveRuntime.builder()
            .name("jitter")
            .workers(Integer.getInteger("gals.workers", Runtime.getRuntime().availableProcessors()))
            .jmx(false)
            .build()) {
      armgals(runtime, length); // warm-up
      IslandStats s = armgals(runtime, length);
      print(out, "armgals", s.jitterP50(), s.jitterP99(), s.jitterMax());
      System.err.println("# armgals island: " + s);
    }
    raw(length); // warm-up
    Histogram h = raw(length);
    print(
        out,
        "raw",
        Duration.ofNanos(h.getValueAtPercentile(50)),
        Duration.ofNanos(h.getValueAtPercentile(99)),
        Duration.ofNanos(h.getMaxValue()));
  }

  private static IslandStats armgals(ActiveRuntime runtime, Duration length) throws Exception {
    Island island = Island.builder("jitter", runtime).period(PERIOD).build();
    try {
      for (int i = 0; i < ENTITIES; i++) {
        island.spawn("e" + i, new long[] {i + 1}, c -> c.state()[0] = Work.cycle(c.state()[0]));
      }
      island.start();
      DeadlinePacer pacer = DeadlinePacer.of(TimeSource.system(), Duration.ZERO);
      pacer.awaitUntil(pacer.time().nanoTime() + length.toNanos()); // the benchmark's length
    } finally {
      island.close();
    }
    return island.stats();
  }

  /**
   * The baseline: park, spin, record the lateness, do the work of every entity, skip on overrun.
   */
  private static Histogram raw(Duration length) {
    TimeSource time = TimeSource.system();
    Histogram h = new Histogram(Duration.ofSeconds(10).toNanos(), 3);
    long[] states = new long[ENTITIES];
    for (int i = 0; i < ENTITIES; i++) {
      states[i] = i + 1;
    }
    long period = PERIOD.toNanos();
    long start = time.nanoTime();
    long end = start + length.toNanos();
    long due = start + period;
    while (due < end) {
      for (long now = time.nanoTime(); now < due; now = time.nanoTime()) {
        if (due - now > SPIN_NANOS) {
          LockSupport.parkNanos(due - now - SPIN_NANOS);
        } else {
          Thread.onSpinWait();
        }
      }
      h.recordValue(Math.min(time.nanoTime() - due, h.getHighestTrackableValue()));
      for (int i = 0; i < ENTITIES; i++) {
        states[i] = Work.cycle(states[i]);
      }
      long finished = time.nanoTime();
      due += period;
      if (finished > due) {
        due += ((finished - due + period - 1) / period) * period;
      }
    }
    long sum = 0;
    for (long s : states) {
      sum += s;
    }
    if (sum == 42) {
      System.err.println("unlikely"); // keeps the work observable
    }
    return h;
  }

  private static void print(
      PrintStream out, String impl, Duration p50, Duration p99, Duration max) {
    out.println(
        String.format(
            Locale.ROOT,
            "gals name=jitter impl=%s hz=%d p50_us=%.1f p99_us=%.1f max_us=%.1f",
            impl,
            Duration.ofSeconds(1).toNanos() / PERIOD.toNanos(),
            p50.toNanos() / 1000.0,
            p99.toNanos() / 1000.0,
            max.toNanos() / 1000.0));
  }
}

package org.armgals.examples.sim;

import java.io.PrintStream;
import java.util.Locale;
import org.armgals.active.TimeSource;

/**
 * Shows how far a run has gone: simulated time, cycles per second of real time and the real-time
 * factor. On a terminal, one bar redrawn in place at most every {@link #REDRAW_NANOS}; otherwise a
 * plain line at each tenth of the run, so that logs stay readable.
 *
 * <p>Used by the thread that runs the simulation only.
 */
final class Progress {
  static final long REDRAW_NANOS = 200_000_000L;
  private static final int BAR = 30;

  private final PrintStream out;
  private final boolean terminal;
  private final long totalCycles;
  private final TimeSource clock;
  private final long startNanos;
  private long lastDrawNanos;
  private int lastTenth;

  Progress(PrintStream out, boolean terminal, long totalCycles, TimeSource clock) {
    this.out = out;
    this.terminal = terminal;
    this.totalCycles = totalCycles;
    this.clock = clock;
    this.startNanos = clock.nanoTime();
    this.lastDrawNanos = startNanos;
  }

  /** Tells that {@code cycles} cycles have run, reaching {@code simulatedNanos} of virtual time. */
  void update(long cycles, long simulatedNanos) {
    long now = clock.nanoTime();
    if (terminal) {
      if (now - lastDrawNanos >= REDRAW_NANOS || cycles == totalCycles) {
        lastDrawNanos = now;
        out.print("\r" + line(cycles, simulatedNanos, now));
        if (cycles == totalCycles) {
          out.println();
        }
        out.flush();
      }
      return;
    }
    int tenth = (int) (cycles * 10 / totalCycles);
    if (tenth > lastTenth) {
      lastTenth = tenth;
      out.println(line(cycles, simulatedNanos, now));
    }
  }

  /** The real time elapsed since the run began (ns). */
  long elapsedNanos() {
    return clock.nanoTime() - startNanos;
  }

  private String line(long cycles, long simulatedNanos, long now) {
    double real = Math.max(1e-9, (now - startNanos) / 1e9);
    double simulated = simulatedNanos / 1e9;
    int filled = (int) (cycles * BAR / totalCycles);
    String bar = terminal ? "[" + "#".repeat(filled) + " ".repeat(BAR - filled) + "] " : "";
    return String.format(
        Locale.ROOT,
        "%s%3d%%  simulated %.2f s  %.0f cycles/s  %.1f× real time",
        bar,
        cycles * 100 / totalCycles,
        simulated,
        cycles / real,
        simulated / real);
  }
}

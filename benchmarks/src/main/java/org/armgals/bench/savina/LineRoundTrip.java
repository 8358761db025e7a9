package org.armgals.bench.savina;

import java.util.Arrays;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicLongArray;
import org.armgals.bench.Args;

/**
 * What moving one cache line between two cores costs on this machine: two threads pass a counter
 * back and forth through two longs on lines of their own, each spinning until the other has
 * written. One round trip moves each line once each way, the least any hand-over between two
 * threads on two cores costs. Run it as {@code java -cp benchmarks.jar
 * org.armgals.bench.savina.LineRoundTrip [--rounds n] [--trips n]} on a machine with two idle cores
 * or more (on one core, each trip waits for the scheduler to switch threads).
 *
 * <p>Prints one line per round, {@code line round_trip_ns=<ns>}, then {@code line
 * median_round_trip_ns=<ns> rounds=<n>}.
 */
public final class LineRoundTrip {
  /** Longs between the two counters: 128 bytes, so that they never share a line or its pair. */
  private static final int GAP = 16;

  private static final int PING = GAP;
  private static final int PONG = 2 * GAP;

  private LineRoundTrip() {}

  /**
   * Runs the rounds.
   *
   * @param args {@code --rounds n} (default 5), {@code --trips n} round trips per round (default
   *     2,000,000)
   * @throws InterruptedException if interrupted while the other thread finishes a round
   */
  public static void main(String[] args) throws InterruptedException {
    int rounds = 5;
    int trips = 2_000_000;
    for (int i = 0; i < args.length; i++) {
      switch (args[i]) {
        case "--rounds" -> rounds = Args.count(Args.value(args, ++i, "--rounds"), "--rounds", 1);
        case "--trips" -> trips = Args.count(Args.value(args, ++i, "--trips"), "--trips", 1);
        default ->
            throw new IllegalArgumentException(
                "unknown argument '" + args[i] + "'; expected --rounds n or --trips n");
      }
    }
    double[] nanos = new double[rounds];
    for (int r = 0; r < rounds; r++) {
      nanos[r] = round(trips);
      System.out.printf(Locale.ROOT, "line round_trip_ns=%.0f%n", nanos[r]);
    }
    Arrays.sort(nanos);
    System.out.printf(
        Locale.ROOT, "line median_round_trip_ns=%.0f rounds=%d%n", nanos[rounds / 2], rounds);
  }

  /** One round of {@code trips} round trips; returns the nanoseconds per round trip. */
  private static double round(int trips) throws InterruptedException {
    AtomicLongArray lines = new AtomicLongArray(3 * GAP);
    Thread echo =
        Thread.ofPlatform()
            .name("line-echo")
            .start(
                () -> {
                  for (long i = 1; i <= trips; i++) {
                    while (lines.get(PING) != i) {
                      Thread.onSpinWait();
                    }
                    lines.set(PONG, i);
                  }
                });
    long start = System.nanoTime();
    for (long i = 1; i <= trips; i++) {
      lines.set(PING, i);
      while (lines.get(PONG) != i) {
        Thread.onSpinWait();
      }
    }
    long elapsed = System.nanoTime() - start;
    echo.join();
    return (double) elapsed / trips;
  }
}

package org.armgals.bench.gals;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * {@code benchmarks/gals.sh}'s entry point: {@code Gals [name...]} runs the named benchmarks (all
 * when none is named), each printing its {@code gals name=...} line(s) on standard output, details
 * on standard error. A new benchmark is one more entry in {@link #BENCHMARKS}.
 */
public final class Gals {

  /** What a benchmark does: prints its lines. */
  @FunctionalInterface
  interface Benchmark {
    void run() throws Exception;
  }

  private static final Map<String, Benchmark> BENCHMARKS = new LinkedHashMap<>();

  static {
    BENCHMARKS.put("reschedule", Reschedule::run);
    BENCHMARKS.put("cycle-overhead", CycleOverhead::run);
    BENCHMARKS.put("island-overhead", IslandOverhead::run);
    BENCHMARKS.put("jitter", JitterBenchmark::run);
  }

  private Gals() {}

  /**
   * Runs the benchmarks named in {@code args}, or all.
   *
   * @throws IllegalArgumentException an unknown name
   */
  public static void main(String[] args) throws Exception {
    List<String> names = args.length == 0 ? new ArrayList<>(BENCHMARKS.keySet()) : List.of(args);
    for (String name : names) {
      if (!BENCHMARKS.containsKey(name)) {
        throw new IllegalArgumentException(
            "benchmark '" + name + "': expected one of " + BENCHMARKS.keySet());
      }
    }
    for (String name : names) {
      BENCHMARKS.get(name).run();
    }
  }
}

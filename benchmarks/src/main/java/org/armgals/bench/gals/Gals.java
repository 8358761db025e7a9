package org.armgals.bench.gals;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Runs the GALS benchmarks and prints one line per measurement, {@code gals name=<name> ...}.
 *
 * <p>Usage: {@code Gals [--seconds s] [name...]}: the names are those of {@link #BENCHMARKS} (no
 * name runs them all); {@code --seconds} (default 5) is how long each measured part runs. A new
 * benchmark is one more entry in {@link #BENCHMARKS}.
 */
public final class Gals {
  private Gals() {}

  /** The benchmarks by name, in the order they run. */
  static final Map<String, GalsBenchmark> BENCHMARKS = new LinkedHashMap<>();

  static {
    register(new JitterBenchmark());
  }

  private static void register(GalsBenchmark b) {
    BENCHMARKS.put(b.name(), b);
  }

  /** Entry point; see the class comment. */
  public static void main(String[] args) throws Exception {
    int seconds = 5;
    List<String> names = new ArrayList<>();
    for (int i = 0; i < args.length; i++) {
      if (args[i].equals("--seconds")) {
        if (i + 1 >= args.length) {
          throw new IllegalArgumentException("--seconds needs a value");
        }
        seconds = Integer.parseInt(args[++i]);
        if (seconds < 1) {
          throw new IllegalArgumentException("--seconds must be >= 1, was " + seconds);
        }
      } else if (BENCHMARKS.containsKey(args[i])) {
        names.add(args[i]);
      } else {
        throw new IllegalArgumentException(
            "unknown benchmark '" + args[i] + "'; expected one of " + BENCHMARKS.keySet());
      }
    }
    if (names.isEmpty()) {
      names.addAll(BENCHMARKS.keySet());
    }
    for (String name : names) {
      BENCHMARKS.get(name).run(seconds, System.out);
    }
  }
}

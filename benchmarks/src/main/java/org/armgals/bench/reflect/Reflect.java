package org.armgals.bench.reflect;

import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.armgals.bench.Args;
import org.armgals.examples.robots.Caterpillar;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.SimExample;

/**
 * {@code benchmarks/reflect.sh}'s entry point: the reflective loop's figures, one {@code reflect
 * name=...} line each on standard output, details on standard error.
 *
 * <ul>
 *   <li>{@code notify-cost}: the CPU a cycle of the 4-atom caterpillar costs with its head
 *       notifying its meta every cycle, against the same robots notifying no one ({@link
 *       NotifyCost});
 *   <li>{@code latency}: the benchmark's example {@link Asking} run paced to real time (free: the
 *       robot never waits for its meta) with its meta in the robots' JVM and in another,
 *       alternated; from each run's summary, the cycles and the real time from a notification to
 *       the request decided on it being applied, median and p99;
 *   <li>{@code missed}: the caterpillar run paced to real time with its meta in another JVM, as
 *       {@code armgals run caterpillar --realtime --meta remote} does, after the same warm-up
 *       ({@code --warmup-seconds}, default {@link RunSettings#DEFAULT_WARMUP}; 0 for none); the
 *       cycles it missed.
 * </ul>
 *
 * <p>Usage: {@code Reflect [--runs n] [--seconds s] [--missed-seconds s] [--warmup-seconds s]
 * [--rounds n] [--cycles n] [--out dir] [name...]}; every line ends with {@code load=<1-minute load
 * average>} read when its figure was taken.
 */
public final class Reflect {
  private static final Duration PERIOD = Duration.ofMillis(10);
  private static final Pattern LATENCY =
      Pattern.compile(
          "(\\d+) cycles \\(median\\), (\\d+) at most \\(p99 (\\d+)\\); (\\d+) µs \\(median\\), p99"
              + " (\\d+) µs of real time");
  private static final Pattern REQUESTS =
      Pattern.compile("(\\d+) \\((\\d+) applied, (\\d+) refused.*");

  private Reflect() {}

  /** The command line: see the class comment. */
  public static void main(String[] args) throws Exception {
    int runs = 3;
    double seconds = 30;
    double missedSeconds = 60;
    double warmupSeconds = RunSettings.DEFAULT_WARMUP.toNanos() / 1e9;
    int rounds = 5;
    int cycles = 3000;
    Path out = Path.of("benchmarks", "target", "reflect");
    Set<String> names = new LinkedHashSet<>();
    for (int i = 0; i < args.length; i++) {
      switch (args[i]) {
        case "--runs" -> runs = Args.count(Args.value(args, ++i, "--runs"), "--runs", 1);
        case "--seconds" -> seconds = positive(Args.value(args, ++i, "--seconds"), "--seconds");
        case "--missed-seconds" ->
            missedSeconds = positive(Args.value(args, ++i, "--missed-seconds"), "--missed-seconds");
        case "--warmup-seconds" ->
            warmupSeconds =
                notNegative(Args.value(args, ++i, "--warmup-seconds"), "--warmup-seconds");
        case "--rounds" -> rounds = Args.count(Args.value(args, ++i, "--rounds"), "--rounds", 1);
        case "--cycles" -> cycles = Args.count(Args.value(args, ++i, "--cycles"), "--cycles", 100);
        case "--out" -> out = Path.of(Args.value(args, ++i, "--out"));
        case "notify-cost", "latency", "missed" -> names.add(args[i]);
        default ->
            throw new IllegalArgumentException(
                "'" + args[i] + "': expected notify-cost, latency, missed or an option");
      }
    }
    if (names.isEmpty()) {
      names.addAll(List.of("notify-cost", "latency", "missed"));
    }
    for (String name : names) {
      switch (name) {
        case "notify-cost" -> new NotifyCost(PERIOD, rounds, cycles, out).run();
        case "latency" -> latency(runs, seconds, out);
        case "missed" -> missed(runs, missedSeconds, warmupSeconds, out);
        default -> throw new AssertionError(name);
      }
    }
  }

  private static double notNegative(String text, String option) {
    try {
      double d = Double.parseDouble(text);
      if (d >= 0 && Double.isFinite(d)) {
        return d;
      }
    } catch (NumberFormatException e) {
      // told below
    }
    throw new IllegalArgumentException(option + " must be 0 or more, was '" + text + "'");
  }

  private static double positive(String text, String option) {
    try {
      double d = Double.parseDouble(text);
      if (d > 0) {
        return d;
      }
    } catch (NumberFormatException e) {
      // told below
    }
    throw new IllegalArgumentException(option + " must be a positive number, was '" + text + "'");
  }

  /**
   * {@link Asking}, free at 100 Hz, its meta local and remote, {@code runs} times each (the order
   * alternated), after a warm-up run of each of 5 s.
   */
  static void latency(int runs, double seconds, Path out) {
    Asking example = new Asking();
    for (RunSettings.MetaPlace place : RunSettings.MetaPlace.values()) {
      Summary warm = run(example, true, place, 5, out.resolve("warm-" + place));
      System.err.println("# warm-up " + place + ": " + loop(warm));
    }
    List<List<Loop>> byPlace = List.of(new ArrayList<>(), new ArrayList<>());
    for (int r = 0; r < runs; r++) {
      for (int k = 0; k < 2; k++) {
        RunSettings.MetaPlace place = RunSettings.MetaPlace.values()[(r + k) % 2];
        String load = load();
        Summary s = run(example, true, place, seconds, out.resolve("latency-" + place + "-" + r));
        Loop l = loop(s);
        byPlace.get(place.ordinal()).add(l);
        System.out.printf(
            Locale.ROOT,
            "reflect name=latency-run meta=%s hz=100 seconds=%s requests=%d applied=%d"
                + " p50_cycles=%d p99_cycles=%d max_cycles=%d p50_us=%d p99_us=%d missed=%d"
                + " overruns=%d load=%s%n",
            place.name().toLowerCase(Locale.ROOT),
            seconds,
            l.requests,
            l.applied,
            l.p50Cycles,
            l.p99Cycles,
            l.maxCycles,
            l.p50Micros,
            l.p99Micros,
            l.missed,
            l.overruns,
            load);
      }
    }
    for (RunSettings.MetaPlace place : RunSettings.MetaPlace.values()) {
      List<Loop> ls = byPlace.get(place.ordinal());
      System.out.printf(
          Locale.ROOT,
          "reflect name=latency meta=%s hz=100 runs=%d requests=%d p50_cycles=%d p99_cycles=%d"
              + " (%d-%d) p50_us=%d p99_us=%d (%d-%d) load=%s%n",
          place.name().toLowerCase(Locale.ROOT),
          ls.size(),
          median(ls.stream().map(l -> (long) l.requests).toList()),
          median(ls.stream().map(l -> l.p50Cycles).toList()),
          median(ls.stream().map(l -> l.p99Cycles).toList()),
          ls.stream().mapToLong(l -> l.p99Cycles).min().orElse(0),
          ls.stream().mapToLong(l -> l.p99Cycles).max().orElse(0),
          median(ls.stream().map(l -> l.p50Micros).toList()),
          median(ls.stream().map(l -> l.p99Micros).toList()),
          ls.stream().mapToLong(l -> l.p99Micros).min().orElse(0),
          ls.stream().mapToLong(l -> l.p99Micros).max().orElse(0),
          load());
    }
  }

  /**
   * The caterpillar, free at 100 Hz, its meta remote, {@code runs} times, each after a warm-up of
   * {@code warmup} simulated seconds.
   */
  static void missed(int runs, double seconds, double warmup, Path out) {
    List<Long> missed = new ArrayList<>();
    for (int r = 0; r < runs; r++) {
      String load = load();
      Summary s =
          run(
              new Caterpillar(),
              true,
              RunSettings.MetaPlace.REMOTE,
              seconds,
              warmup,
              out.resolve("missed-" + r));
      Loop l = loop(s);
      missed.add(l.missed);
      System.out.printf(
          Locale.ROOT,
          "reflect name=missed-run robot=caterpillar meta=remote hz=100 seconds=%s warmup_s=%s"
              + " missed=%d overruns=%d requests=%d load=%s%n",
          seconds,
          warmup,
          l.missed,
          l.overruns,
          l.requests,
          load);
    }
    System.out.printf(
        Locale.ROOT,
        "reflect name=missed robot=caterpillar meta=remote hz=100 seconds=%s warmup_s=%s runs=%d"
            + " missed=%d (%d-%d) load=%s%n",
        seconds,
        warmup,
        runs,
        median(missed),
        missed.stream().mapToLong(Long::longValue).min().orElse(0),
        missed.stream().mapToLong(Long::longValue).max().orElse(0),
        load());
  }

  /** Runs {@code example} as {@code armgals run} does, its progress and summary on stderr. */
  static Summary run(
      SimExample example, boolean realTime, RunSettings.MetaPlace place, double seconds, Path out) {
    return run(example, realTime, place, seconds, 0, out);
  }

  /** As above, after a warm-up of {@code warmup} simulated seconds (paced runs only). */
  static Summary run(
      SimExample example,
      boolean realTime,
      RunSettings.MetaPlace place,
      double seconds,
      double warmup,
      Path out) {
    try {
      Files.createDirectories(out);
    } catch (IOException e) {
      throw new UncheckedIOException("cannot make " + out, e);
    }
    RunSettings settings =
        new RunSettings(
            OptionalLong.empty(),
            Optional.of(Duration.ofNanos(Math.round(seconds * 1e9))),
            PERIOD,
            1,
            Optional.empty(),
            realTime,
            Optional.empty(),
            out,
            place,
            Duration.ofNanos(Math.round(warmup * 1e9)));
    PrintStream err = System.err;
    Summary summary = example.run(settings, err);
    for (Summary.Entry e : summary.entries()) {
      if (!e.name().startsWith("  at ")) {
        err.println("#   " + e.name() + ": " + e.value());
      }
    }
    return summary;
  }

  /** What a run's summary says of its loop. */
  record Loop(
      int requests,
      int applied,
      long p50Cycles,
      long p99Cycles,
      long maxCycles,
      long p50Micros,
      long p99Micros,
      long missed,
      long overruns) {}

  static Loop loop(Summary s) {
    String latency = value(s, "notified to applied").orElse("");
    Matcher m = LATENCY.matcher(latency);
    boolean timed = m.matches();
    Matcher q = REQUESTS.matcher(value(s, "requests").orElse(""));
    boolean asked = q.matches();
    return new Loop(
        asked ? Integer.parseInt(q.group(1)) : 0,
        asked ? Integer.parseInt(q.group(2)) : 0,
        timed ? Long.parseLong(m.group(1)) : -1,
        timed ? Long.parseLong(m.group(3)) : -1,
        timed ? Long.parseLong(m.group(2)) : -1,
        timed ? Long.parseLong(m.group(4)) : -1,
        timed ? Long.parseLong(m.group(5)) : -1,
        Long.parseLong(value(s, "missed cycles").orElseThrow()),
        value(s, "adaptation overruns").map(v -> Long.parseLong(v.split(" ")[0])).orElse(0L));
  }

  private static Optional<String> value(Summary s, String name) {
    return s.entries().stream()
        .filter(e -> e.name().equals(name))
        .map(Summary.Entry::value)
        .findFirst();
  }

  static long median(List<Long> values) {
    if (values.isEmpty()) {
      return -1;
    }
    List<Long> sorted = new ArrayList<>(values);
    sorted.sort(null);
    return sorted.get(sorted.size() / 2);
  }

  /** The 1-minute load average now, as {@code uptime} shows it. */
  static String load() {
    try {
      return Files.readString(Path.of("/proc/loadavg")).split(" ")[0];
    } catch (IOException | RuntimeException e) {
      return String.format(
          Locale.ROOT,
          "%.2f",
          java.lang.management.ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
    }
  }
}

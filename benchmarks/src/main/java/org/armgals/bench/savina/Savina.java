package org.armgals.bench.savina;

import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.LongSupplier;
import org.armgals.active.TimeSource;
import org.armgals.bench.Args;
import org.armgals.bench.savina.armgals.ArmgalsSuite;
import org.armgals.bench.savina.pekko.PekkoSuite;
import org.armgals.bench.savina.yardstick.YardstickSuite;

/**
 * Runs the Savina-style suite for one implementation and prints one line per run:
 *
 * <pre>
 * [warmup ]savina name=&lt;bench&gt; impl=&lt;impl&gt; ops=&lt;n&gt; seconds=&lt;t&gt; ops_per_s=&lt;x&gt; cpu_s=&lt;c&gt; cpu_s_per_m_ops=&lt;y&gt;
 * mem impl=&lt;impl&gt; bytes_per_idle_object=&lt;b&gt;
 * </pre>
 *
 * <p>{@code cpu_s} is the CPU time the whole process (every thread: the runtime's, the caller's,
 * the collector's and the compiler's) spent during the timed part of the run, from {@link
 * com.sun.management.OperatingSystemMXBean#getProcessCpuTime()}; {@code cpu_s_per_m_ops} is that
 * per million operations (equal to the CPU microseconds per operation). A CPU idle-spinning thread
 * shows there, not in {@code ops_per_s}.
 *
 * <p>Usage: {@code Savina [--impl armgals|pekko|yardstick] [--warmup n] [--warmup-seconds s]
 * [--runs n] [name...]} where a name is one of {@link #WORKLOADS} or {@code mem}; no name runs them
 * all. Each workload is warmed up by at least {@code n} runs (default 2) and at least {@code s}
 * seconds (default 5), so that a workload whose run is short gets as much warm-up time as one whose
 * run is long, then measured {@code --runs} times (default 3). Sizes come from {@link
 * Sizes#fromSystemProperties()}. {@code benchmarks/savina.sh} runs each name in a JVM of its own.
 * Exits with status 1, after the stack trace, if a run fails its check.
 */
public final class Savina {
  /** The timed workloads, in the order they run. */
  public static final List<String> WORKLOADS =
      List.of("pingpong", "counting", "threadring", "fjthrput", "creation", "futurertt");

  /** The memory probe's name. */
  public static final String MEM = "mem";

  private final Suite suite;
  private final Sizes sizes;
  private final TimeSource time;
  private final LongSupplier cpuNanos;
  private final PrintStream out;

  Savina(Suite suite, Sizes sizes, TimeSource time, LongSupplier cpuNanos, PrintStream out) {
    this.suite = suite;
    this.sizes = sizes;
    this.time = time;
    this.cpuNanos = cpuNanos;
    this.out = out;
  }

  /** How a workload is warmed up and measured. */
  record Plan(int warmupRuns, long warmupNanos, int runs) {}

  /** Entry point; see the class comment. */
  public static void main(String[] args) throws Exception {
    String impl = "armgals";
    int warmup = 2;
    int warmupSeconds = 5;
    int runs = 3;
    List<String> names = new ArrayList<>();
    for (int i = 0; i < args.length; i++) {
      switch (args[i]) {
        case "--impl" -> impl = Args.value(args, ++i, "--impl");
        case "--warmup" -> warmup = Args.count(Args.value(args, ++i, "--warmup"), "--warmup", 0);
        case "--warmup-seconds" ->
            warmupSeconds =
                Args.count(Args.value(args, ++i, "--warmup-seconds"), "--warmup-seconds", 0);
        case "--runs" -> runs = Args.count(Args.value(args, ++i, "--runs"), "--runs", 1);
        default -> names.add(known(args[i]));
      }
    }
    if (names.isEmpty()) {
      names.addAll(WORKLOADS);
      names.add(MEM);
    }
    Sizes sizes = Sizes.fromSystemProperties();
    Plan plan = new Plan(warmup, warmupSeconds * 1_000_000_000L, runs);
    try (Suite suite = suite(impl, sizes)) {
      Savina savina = new Savina(suite, sizes, TimeSource.system(), processCpuNanos(), System.out);
      for (String name : names) {
        if (name.equals(MEM)) {
          savina.measureMemory();
        } else {
          savina.measure(name, plan);
        }
      }
    } catch (Exception e) {
      // A failed check must end the JVM even if a runtime left non-daemon threads behind.
      org.slf4j.LoggerFactory.getLogger(Savina.class).error("savina: the run failed", e);
      System.exit(1);
    }
    // Lingering non-daemon threads of a runtime must not keep a finished run alive.
    System.exit(0);
  }

  /**
   * The process's CPU time in nanoseconds, summed over all its threads.
   *
   * @throws IllegalStateException the JVM does not measure it
   */
  private static LongSupplier processCpuNanos() {
    com.sun.management.OperatingSystemMXBean os =
        ManagementFactory.getPlatformMXBean(com.sun.management.OperatingSystemMXBean.class);
    Check.state(
        os != null && os.getProcessCpuTime() >= 0, "this JVM does not measure the process's CPU");
    return os::getProcessCpuTime;
  }

  private static Suite suite(String impl, Sizes sizes) {
    return switch (impl) {
      case "armgals" -> new ArmgalsSuite(sizes);
      case "pekko" -> new PekkoSuite(sizes);
      case "yardstick" -> new YardstickSuite(sizes);
      default ->
          throw new IllegalArgumentException(
              "unknown implementation '" + impl + "'; expected armgals, pekko or yardstick");
    };
  }

  /** Warm-up runs, then measured runs, of one workload. */
  void measure(String name, Plan plan) throws Exception {
    Workload workload = suite.workload(name);
    long warmupEnd = time.nanoTime() + plan.warmupNanos();
    for (int i = 0; i < plan.warmupRuns() || time.nanoTime() - warmupEnd < 0; i++) {
      runOnce(name, workload, "warmup ");
    }
    for (int i = 0; i < plan.runs(); i++) {
      runOnce(name, workload, "");
    }
  }

  private void runOnce(String name, Workload workload, String prefix) throws Exception {
    try (Trial trial = workload.prepare()) {
      System.gc();
      long cpuStart = cpuNanos.getAsLong();
      long start = time.nanoTime();
      long ops = trial.run();
      double seconds = (time.nanoTime() - start) / 1e9;
      double cpuSeconds = (cpuNanos.getAsLong() - cpuStart) / 1e9;
      out.printf(
          Locale.ROOT,
          "%ssavina name=%s impl=%s ops=%d seconds=%.3f ops_per_s=%.0f cpu_s=%.3f"
              + " cpu_s_per_m_ops=%.3f%n",
          prefix,
          name,
          suite.impl(),
          ops,
          seconds,
          ops / seconds,
          cpuSeconds,
          cpuSeconds / ops * 1e6);
    }
  }

  /** The heap per idle object. */
  void measureMemory() throws Exception {
    double bytes = HeapProbe.bytesPerIdleObject(suite.idleObjects(), sizes.memObjects());
    out.printf(
        Locale.ROOT, "mem impl=%s bytes_per_idle_object=%.0f%n", suite.impl(), Math.ceil(bytes));
  }

  private static String known(String name) {
    if (!WORKLOADS.contains(name) && !name.equals(MEM)) {
      throw new IllegalArgumentException(
          "unknown workload '" + name + "'; expected one of " + WORKLOADS + " or " + MEM);
    }
    return name;
  }
}

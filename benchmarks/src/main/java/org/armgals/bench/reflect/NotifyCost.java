package org.armgals.bench.reflect;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalLong;
import org.armgals.examples.robots.Caterpillar;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.sim.Crew;
import org.armgals.examples.sim.Journal;
import org.armgals.examples.sim.SimExample;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.sim.SimulationBuilder;
import org.armgals.maam.sim.spi.Pacer;

/**
 * What notifying its meta every cycle costs the 4-atom caterpillar: the CPU of a cycle of {@link
 * Caterpillar} (its head notifying its meta level of its state every cycle) minus that of {@link
 * Caterpillar#withoutMetaLevel()} (the same robots on the same islands, the head notifying no one),
 * taken in rounds that alternate the two, each round a new simulation whose first cycles are left
 * out, after warm-up rounds. Three pacings:
 *
 * <ul>
 *   <li>{@code lockstep}: virtual time as fast as it goes, the head in lock step with its meta (it
 *       waits at each cycle for the meta to have handled the previous one): {@code armgals run
 *       caterpillar};
 *   <li>{@code free}: virtual time as fast as it goes, the head never waiting for its meta;
 *   <li>{@code realtime}: paced to real time at 100 Hz, free: {@code armgals run caterpillar
 *       --realtime} (fewer cycles a round: a cycle takes 10 ms).
 * </ul>
 *
 * Each side's figure is the CPU of the whole process during the measured cycles ({@code
 * OperatingSystemMXBean#getProcessCpuTime}: every thread, the simulation's physics, the robots'
 * runtime, the meta, the collector and the compiler) divided by the cycles; also the sum of the
 * Java threads' CPU ({@code ThreadMXBean}, finer grained, without the collector and the compiler)
 * and that of the simulation's thread alone (the physics and the islands' releases). The cost is
 * the median of the rounds' differences, with meta minus without, the same round.
 */
final class NotifyCost {
  private static final int SETTLE = 200;
  private static final int WARM_ROUNDS = 2;
  private static final int REALTIME_CYCLES = 500;

  private static final Journal NO_JOURNAL =
      new Journal() {
        @Override
        public void adaptation(int atom, String what, String why) {}

        @Override
        public void note(int atom, String text) {}
      };

  private final Duration period;
  private final int rounds;
  private final int cycles;
  private final Path out;
  private final ThreadMXBean threads = ManagementFactory.getThreadMXBean();
  private final com.sun.management.OperatingSystemMXBean os =
      (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();

  NotifyCost(Duration period, int rounds, int cycles, Path out) {
    this.period = period;
    this.rounds = rounds;
    this.cycles = cycles;
    this.out = out;
  }

  /** What a round measured, per cycle: process, Java threads, the simulation's thread, ns. */
  record Cpu(double process, double threads, double sim) {}

  void run() {
    SimExample with = new Caterpillar();
    SimExample without = Caterpillar.withoutMetaLevel();
    for (String pacing : List.of("lockstep", "free", "realtime")) {
      int n = pacing.equals("realtime") ? Math.min(cycles, REALTIME_CYCLES) : cycles;
      for (int w = 0; w < (pacing.equals("lockstep") ? WARM_ROUNDS : 1); w++) {
        Cpu a = round(with, pacing, n);
        Cpu b = round(without, pacing, n);
        System.err.printf(
            Locale.ROOT,
            "# warm-up %s: with %.0f ns, without %.0f ns a cycle%n",
            pacing,
            a.process(),
            b.process());
      }
      List<Cpu> withs = new ArrayList<>();
      List<Cpu> withouts = new ArrayList<>();
      String load = Reflect.load();
      for (int r = 0; r < rounds; r++) {
        boolean withFirst = r % 2 == 0;
        Cpu first = round(withFirst ? with : without, pacing, n);
        Cpu second = round(withFirst ? without : with, pacing, n);
        Cpu a = withFirst ? first : second;
        Cpu b = withFirst ? second : first;
        withs.add(a);
        withouts.add(b);
        System.err.printf(
            Locale.ROOT,
            "# %s round %d: with %.0f ns (threads %.0f, sim %.0f), without %.0f ns (threads %.0f,"
                + " sim %.0f) a cycle; load %s%n",
            pacing,
            r,
            a.process(),
            a.threads(),
            a.sim(),
            b.process(),
            b.threads(),
            b.sim(),
            Reflect.load());
      }
      List<Double> diff = new ArrayList<>();
      List<Double> threadDiff = new ArrayList<>();
      List<Double> offSim = new ArrayList<>();
      for (int r = 0; r < rounds; r++) {
        diff.add(withs.get(r).process() - withouts.get(r).process());
        threadDiff.add(withs.get(r).threads() - withouts.get(r).threads());
        offSim.add(
            (withs.get(r).threads() - withs.get(r).sim())
                - (withouts.get(r).threads() - withouts.get(r).sim()));
      }
      double cost = median(diff);
      System.out.printf(
          Locale.ROOT,
          "reflect name=notify-cost pacing=%s atoms=4 cost_ns=%.0f share_pct=%.3f min_ns=%.0f"
              + " max_ns=%.0f threads_cost_ns=%.0f off_sim_thread_cost_ns=%.0f with_ns=%.0f"
              + " without_ns=%.0f rounds=%d cycles=%d load=%s-%s%n",
          pacing,
          cost,
          100 * cost / period.toNanos(),
          diff.stream().mapToDouble(Double::doubleValue).min().orElse(0),
          diff.stream().mapToDouble(Double::doubleValue).max().orElse(0),
          median(threadDiff),
          median(offSim),
          median(withs.stream().map(Cpu::process).toList()),
          median(withouts.stream().map(Cpu::process).toList()),
          rounds,
          n,
          load,
          Reflect.load());
    }
  }

  /** One round: a new simulation of {@code example}, {@link #SETTLE} cycles, then n measured. */
  private Cpu round(SimExample example, String pacing, int n) {
    boolean free = !pacing.equals("lockstep");
    RunSettings settings =
        new RunSettings(
            OptionalLong.of(SETTLE + (long) n),
            Optional.empty(),
            period,
            1,
            Optional.of(Caterpillar.DEFAULT_ATOMS),
            free,
            Optional.empty(),
            out,
            RunSettings.MetaPlace.LOCAL);
    SimulationBuilder builder =
        Simulation.builder(example.scene(settings)).seed(settings.seed()).controlPeriod(period);
    if (pacing.equals("realtime")) {
      builder.pacer(Pacer.realTime());
    }
    try (Simulation sim = builder.build()) {
      Crew crew = example.start(sim, settings, NO_JOURNAL);
      try {
        for (int i = 0; i < SETTLE; i++) {
          sim.runCycle();
        }
        Map<Long, Long> before = threadTimes();
        Map<String, Long> tasksBefore = taskTimes();
        long process = os.getProcessCpuTime();
        long simThread = threads.getCurrentThreadCpuTime();
        for (int i = 0; i < n; i++) {
          sim.runCycle();
        }
        simThread = threads.getCurrentThreadCpuTime() - simThread;
        process = os.getProcessCpuTime() - process;
        Map<String, Long> tasksAfter = taskTimes();
        if (!tasksAfter.isEmpty()) {
          process = 0;
          for (Map.Entry<String, Long> e : tasksAfter.entrySet()) {
            process += e.getValue() - tasksBefore.getOrDefault(e.getKey(), 0L);
          }
        }
        Map<Long, Long> after = threadTimes();
        long javaThreads = 0;
        for (Map.Entry<Long, Long> e : after.entrySet()) {
          javaThreads += e.getValue() - before.getOrDefault(e.getKey(), 0L);
        }
        return new Cpu((double) process / n, (double) javaThreads / n, (double) simThread / n);
      } finally {
        crew.close();
      }
    }
  }

  /**
   * The CPU time of each thread of the process in nanoseconds, Java's and the JVM's own, by the
   * kernel's scheduler ({@code /proc/self/task/<tid>/schedstat}); empty where there is no such
   * file, and then the process's CPU time, in clock ticks, is used instead.
   */
  private static Map<String, Long> taskTimes() {
    Map<String, Long> times = new HashMap<>();
    try (java.util.stream.Stream<Path> tasks =
        java.nio.file.Files.list(Path.of("/proc/self/task"))) {
      for (Path task : tasks.toList()) {
        try {
          String stat = java.nio.file.Files.readString(task.resolve("schedstat"));
          times.put(task.getFileName().toString(), Long.parseLong(stat.split(" ")[0]));
        } catch (java.io.IOException | NumberFormatException e) {
          // the thread ended meanwhile
        }
      }
    } catch (java.io.IOException | RuntimeException e) {
      return Map.of();
    }
    return times;
  }

  private Map<Long, Long> threadTimes() {
    Map<Long, Long> times = new HashMap<>();
    for (long id : threads.getAllThreadIds()) {
      long t = threads.getThreadCpuTime(id);
      if (t >= 0) {
        times.put(id, t);
      }
    }
    return times;
  }

  private static double median(List<Double> values) {
    List<Double> sorted = new ArrayList<>(values);
    sorted.sort(null);
    int n = sorted.size();
    return n % 2 == 1 ? sorted.get(n / 2) : (sorted.get(n / 2 - 1) + sorted.get(n / 2)) / 2;
  }
}

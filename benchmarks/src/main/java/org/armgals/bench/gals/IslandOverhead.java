package org.armgals.bench.gals;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.armgals.active.ActiveRuntime;
import org.armgals.gals.Island;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.KernelOptions;
import org.armgals.kernel.NotificationPolicy;
import org.armgals.kernel.StructuralMeta;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.RobotKind;
import org.armgals.representation.p.PState;

/**
 * {@code gals name=island-overhead robots=<n> cpu_ratio=<x> min=<a> max=<b> wall_ratio=<w>
 * island_cpu_us=<i> hand_cpu_us=<h>}: what running robots on an arm-gals island costs, against
 * stepping the same kind of robots by hand. {@value #ROBOTS} robots of 50 modules (those of {@code
 * cycle-overhead}) are entities of one island, which {@link Island#step(long)} releases {@value
 * #INSTANTS} times a round as fast as it can (no clock), each a kernel entity that notifies no one
 * (its cycle's reified step and state are kept, not sent); {@value #ROBOTS} other robots are
 * stepped by hand on the measuring thread as many times, one after the other.
 *
 * <p>Unlike {@code cycle-overhead}, the island's work is spread over its runtime's workers, so it
 * is timed in the whole process's CPU time ({@code com.sun.management.OperatingSystemMXBean}),
 * which also counts the workers' spinning and waking, the collector and the compiler, for both
 * sides. Rounds alternate the two; after at least {@value #WARMUP_ROUNDS} rounds and 5 s, {@value
 * #ROUNDS} rounds are measured: {@code cpu_ratio} is the median of their ratios of CPU time, {@code
 * min} and {@code max} its extremes, {@code wall_ratio} the median ratio of wall time, and {@code
 * island_cpu_us} and {@code hand_cpu_us} the median CPU microseconds of one instant (all robots
 * once) of each.
 */
final class IslandOverhead {

  private static final int ROBOTS = 10;
  private static final int INSTANTS = 20_000;
  private static final int WARMUP_ROUNDS = 5;
  private static final long WARMUP_NANOS = 5_000_000_000L;
  private static final int ROUNDS = 7;

  private IslandOverhead() {}

  static void run() throws Exception {
    com.sun.management.OperatingSystemMXBean os =
        ManagementFactory.getPlatformMXBean(com.sun.management.OperatingSystemMXBean.class);
    List<AbstractRobot> hand = new ArrayList<>();
    List<CycleOverhead.ConstantBody> bodies = new ArrayList<>();
    int workers = Integer.getInteger("gals.workers", Runtime.getRuntime().availableProcessors());
    try (ActiveRuntime runtime =
            ActiveRuntime.builder().name("island-overhead").workers(workers).jmx(false).build();
        Kernel kernel =
            org.armgals.kernel.StructuralMeta.bootstrap(
                runtime, KernelOptions.defaults().withJmx(false));
        Island island = Island.builder("overhead", runtime).jmx(false).build()) {
      StructuralMeta<PState> kind = null;
      List<AbstractRobot> hosted = new ArrayList<>();
      for (int r = 0; r < ROBOTS; r++) {
        CycleOverhead.ConstantBody body = new CycleOverhead.ConstantBody();
        bodies.add(body);
        AbstractRobot robot = CycleOverhead.robot("robot" + r, body, new ArrayList<>());
        if (kind == null) {
          kind = RobotKind.define(kernel, "BenchRobot", robot.observation());
        }
        robot.start(
            island,
            kind,
            kernel.basicBehavioralMeta(),
            island.entityOptions().withNotification(NotificationPolicy.quiet()));
        hosted.add(robot);
        CycleOverhead.ConstantBody handBody = new CycleOverhead.ConstantBody();
        bodies.add(handBody);
        hand.add(CycleOverhead.robot("hand" + r, handBody, new ArrayList<>()));
      }
      long[] times = new long[4];
      long warmupEnd = System.nanoTime() + WARMUP_NANOS;
      for (int w = 0; w < WARMUP_ROUNDS || System.nanoTime() - warmupEnd < 0; w++) {
        round(island, hand, os, times);
      }
      double[] cpu = new double[ROUNDS];
      double[] wall = new double[ROUNDS];
      double[] islandUs = new double[ROUNDS];
      double[] handUs = new double[ROUNDS];
      for (int i = 0; i < ROUNDS; i++) {
        round(island, hand, os, times);
        cpu[i] = (double) times[0] / times[1];
        wall[i] = (double) times[2] / times[3];
        islandUs[i] = times[0] / 1e3 / INSTANTS;
        handUs[i] = times[1] / 1e3 / INSTANTS;
      }
      for (AbstractRobot robot : hosted) {
        if (robot.errors() != 0 || robot.cycles() == 0) {
          throw new IllegalStateException(
              robot.name() + " did not run: " + robot.errors() + " errors");
        }
      }
      for (CycleOverhead.ConstantBody body : bodies) {
        if (body.commands == 0) {
          throw new IllegalStateException("a robot's motor was never commanded");
        }
      }
      double[] sorted = cpu.clone();
      Arrays.sort(sorted);
      System.err.printf(
          Locale.ROOT,
          "# island-overhead: %d robots of 50 modules released by an island of %d workers"
              + " (step, no clock) against %d stepped by hand on one thread; process CPU time;"
              + " rounds of %d instants, CPU ratios:%s%n",
          ROBOTS,
          workers,
          ROBOTS,
          INSTANTS,
          format(cpu));
      System.out.printf(
          Locale.ROOT,
          "gals name=island-overhead robots=%d cpu_ratio=%.2f min=%.2f max=%.2f wall_ratio=%.2f"
              + " island_cpu_us=%.1f hand_cpu_us=%.1f%n",
          ROBOTS,
          median(cpu),
          sorted[0],
          sorted[sorted.length - 1],
          median(wall),
          median(islandUs),
          median(handUs));
    }
  }

  /**
   * One round: {@value #INSTANTS} instants of the island, then as many of the hand-stepped robots;
   * {@code times} gets their process CPU nanoseconds, then their wall nanoseconds.
   */
  private static void round(
      Island island,
      List<AbstractRobot> hand,
      com.sun.management.OperatingSystemMXBean os,
      long[] times) {
    long cpu0 = os.getProcessCpuTime();
    long wall0 = System.nanoTime();
    island.step(INSTANTS);
    long wall1 = System.nanoTime();
    long cpu1 = os.getProcessCpuTime();
    for (int i = 0; i < INSTANTS; i++) {
      for (AbstractRobot robot : hand) {
        robot.cycle();
      }
    }
    long wall2 = System.nanoTime();
    long cpu2 = os.getProcessCpuTime();
    times[0] = cpu1 - cpu0;
    times[1] = cpu2 - cpu1;
    times[2] = wall1 - wall0;
    times[3] = wall2 - wall1;
  }

  private static String format(double[] values) {
    StringBuilder b = new StringBuilder();
    for (double v : values) {
      b.append(String.format(Locale.ROOT, " %.2f", v));
    }
    return b.toString();
  }

  private static double median(double[] values) {
    double[] sorted = values.clone();
    Arrays.sort(sorted);
    int n = sorted.length;
    return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
  }
}

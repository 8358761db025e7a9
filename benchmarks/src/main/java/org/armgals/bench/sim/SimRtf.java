package org.armgals.bench.sim;

import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.time.Duration;
import org.armgals.active.TimeSource;
import org.armgals.maam.sim.LegDynamics;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.sim.spi.Controller;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;

/**
 * Measures the real-time factor of maam-sim: {@code n} atoms in tripod pose on a grid, each run by
 * a simple controller that reads its sensors and swings its three upper legs, at a fixed physics
 * step and a 10 ms control period, with kinematic (default) or jointed legs, on one thread or more.
 * Prints {@code sim name=rtf atoms=<n> step_ms=<s> rtf=<x> legs=<kinematic|jointed> threads=<t>
 * cpu_rtf=<y> us_per_atom_step=<z>}: {@code rtf} is virtual seconds per second of the wall clock,
 * {@code cpu_rtf} per second of the simulating threads' CPU time (what the figure would be on a
 * machine of its own with one core), and {@code us_per_atom_step} that CPU time per atom and
 * physics step, in microseconds.
 *
 * <p>Usage: {@code SimRtf [--step-ms s] [--warmup-seconds w] [--seconds m] [--legs l] [--threads t]
 * n...}
 */
public final class SimRtf {

  private final TimeSource time;
  private final PrintStream out;
  private final ThreadMXBean cpuTime = ManagementFactory.getThreadMXBean();

  SimRtf(TimeSource time, PrintStream out) {
    this.time = time;
    this.out = out;
  }

  /** The command line: see the class comment. */
  public static void main(String[] args) {
    double stepMs = 1;
    double warmup = 2;
    double seconds = 3;
    LegDynamics legs = LegDynamics.KINEMATIC;
    int threads = 1;
    java.util.List<Integer> sizes = new java.util.ArrayList<>();
    for (int i = 0; i < args.length; i++) {
      switch (args[i]) {
        case "--step-ms" -> stepMs = Double.parseDouble(args[++i]);
        case "--warmup-seconds" -> warmup = Double.parseDouble(args[++i]);
        case "--seconds" -> seconds = Double.parseDouble(args[++i]);
        case "--legs" -> legs = legs(args[++i]);
        case "--threads" -> threads = threads(args[++i]);
        default -> sizes.add(Integer.parseInt(args[i]));
      }
    }
    if (sizes.isEmpty()) {
      sizes = java.util.List.of(1, 10, 100, 1000);
    }
    SimRtf bench = new SimRtf(TimeSource.system(), System.out);
    for (int n : sizes) {
      bench.run(n, stepMs, warmup, seconds, legs, threads);
    }
  }

  private static int threads(String text) {
    int n = Integer.parseInt(text);
    if (n < 1) {
      throw new IllegalArgumentException("--threads " + n + ": expected at least 1");
    }
    return n;
  }

  private static LegDynamics legs(String name) {
    for (LegDynamics d : LegDynamics.values()) {
      if (d.name().equalsIgnoreCase(name)) {
        return d;
      }
    }
    throw new IllegalArgumentException("--legs '" + name + "': expected kinematic or jointed");
  }

  void run(
      int atoms,
      double stepMs,
      double warmupSeconds,
      double seconds,
      LegDynamics legs,
      int threads) {
    Duration step = Duration.ofNanos(Math.round(stepMs * 1e6));
    Duration period = step.multipliedBy(Math.max(1, Math.round(10 / stepMs)));
    try (Simulation sim =
        Simulation.builder(Scenes.grid(atoms, 0.4))
            .legDynamics(legs)
            .threads(threads)
            .physicsStep(step)
            .controlPeriod(period)
            .controllers(SimRtf::swing)
            .build()) {
      runFor(sim, warmupSeconds);
      long virtualStart = sim.timeNanos();
      long realStart = time.nanoTime();
      long cpuStart = simulationCpuNanos();
      runFor(sim, seconds);
      long cpu = simulationCpuNanos() - cpuStart;
      long virtual = sim.timeNanos() - virtualStart;
      double rtf = virtual / (double) (time.nanoTime() - realStart);
      double atomSteps = (double) atoms * virtual / step.toNanos();
      out.printf(
          java.util.Locale.ROOT,
          "sim name=rtf atoms=%d step_ms=%s rtf=%.3f legs=%s threads=%d cpu_rtf=%.3f"
              + " us_per_atom_step=%.3f%n",
          atoms,
          stepMs,
          rtf,
          legs.name().toLowerCase(java.util.Locale.ROOT),
          threads,
          virtual / (double) cpu,
          cpu / 1e3 / atomSteps);
    }
  }

  /**
   * The CPU time of the threads that simulate: this one and the simulation's lanes (named {@code
   * maam-sim-...-lane-n}).
   */
  private long simulationCpuNanos() {
    long total = cpuTime.getCurrentThreadCpuTime();
    for (java.lang.management.ThreadInfo t : cpuTime.getThreadInfo(cpuTime.getAllThreadIds())) {
      if (t != null && t.getThreadName().startsWith("maam-sim-")) {
        long nanos = cpuTime.getThreadCpuTime(t.getThreadId());
        total += Math.max(0, nanos);
      }
    }
    return total;
  }

  /** Runs control cycles until {@code seconds} of real time have passed (at least one cycle). */
  private void runFor(Simulation sim, double seconds) {
    long end = time.nanoTime() + (long) (seconds * 1e9);
    do {
      sim.runCycle();
    } while (time.nanoTime() < end);
  }

  /**
   * Reads the body's battery and swings the three upper legs of the tripod, each in its own plane
   * (the diagonal one a little wider): confined to its atom, so on several threads the controllers
   * run at once.
   */
  private static Controller swing(int id) {
    return Controller.confined(
        (body, cycle) -> {
          double energy = body.read(Atom.BATTERY);
          double a = energy > 0 ? 0.4 * Math.sin(cycle * 0.05 + id) : 0;
          body.command(Atom.target(Leg.PX), LegAngles.swing(a, -Math.PI / 2));
          body.command(Atom.target(Leg.PY), LegAngles.swing(a, 0));
          body.command(Atom.target(Leg.PZ), LegAngles.swing(Math.sqrt(2) * a, -3 * Math.PI / 4));
        });
  }
}

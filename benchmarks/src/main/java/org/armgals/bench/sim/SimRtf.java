package org.armgals.bench.sim;

import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.time.Duration;
import org.armgals.active.TimeSource;
import org.armgals.maam.sim.AtomBody;
import org.armgals.maam.sim.LegDynamics;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.sim.spi.Controller;
import org.armgals.maam.spi.Leg;

/**
 * Measures the real-time factor of maam-sim: {@code n} atoms in tripod pose on a grid, each run by
 * a simple controller that reads its sensors and swings its three upper legs, at a fixed physics
 * step and a 10 ms control period, with kinematic (default) or jointed legs. Prints {@code sim
 * name=rtf atoms=<n> step_ms=<s> rtf=<x> legs=<kinematic|jointed> cpu_rtf=<y>
 * us_per_atom_step=<z>}: {@code rtf} is virtual seconds per second of the wall clock, {@code
 * cpu_rtf} per second of the simulating thread's CPU time (what the figure would be on a machine of
 * its own), and {@code us_per_atom_step} that CPU time per atom and physics step, in microseconds.
 *
 * <p>Usage: {@code SimRtf [--step-ms s] [--warmup-seconds w] [--seconds m] [--legs l] n...}
 */
public final class SimRtf {

  private final TimeSource time;
  private final PrintStream out;
  private final ThreadMXBean threads = ManagementFactory.getThreadMXBean();

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
    java.util.List<Integer> sizes = new java.util.ArrayList<>();
    for (int i = 0; i < args.length; i++) {
      switch (args[i]) {
        case "--step-ms" -> stepMs = Double.parseDouble(args[++i]);
        case "--warmup-seconds" -> warmup = Double.parseDouble(args[++i]);
        case "--seconds" -> seconds = Double.parseDouble(args[++i]);
        case "--legs" -> legs = legs(args[++i]);
        default -> sizes.add(Integer.parseInt(args[i]));
      }
    }
    if (sizes.isEmpty()) {
      sizes = java.util.List.of(1, 10, 100, 1000);
    }
    SimRtf bench = new SimRtf(TimeSource.system(), System.out);
    for (int n : sizes) {
      bench.run(n, stepMs, warmup, seconds, legs);
    }
  }

  private static LegDynamics legs(String name) {
    for (LegDynamics d : LegDynamics.values()) {
      if (d.name().equalsIgnoreCase(name)) {
        return d;
      }
    }
    throw new IllegalArgumentException("--legs '" + name + "': expected kinematic or jointed");
  }

  void run(int atoms, double stepMs, double warmupSeconds, double seconds, LegDynamics legs) {
    Duration step = Duration.ofNanos(Math.round(stepMs * 1e6));
    Duration period = step.multipliedBy(Math.max(1, Math.round(10 / stepMs)));
    try (Simulation sim =
        Simulation.builder(Scenes.grid(atoms, 0.4))
            .legDynamics(legs)
            .physicsStep(step)
            .controlPeriod(period)
            .controllers(SimRtf::swing)
            .build()) {
      runFor(sim, warmupSeconds);
      long virtualStart = sim.timeNanos();
      long realStart = time.nanoTime();
      long cpuStart = threads.getCurrentThreadCpuTime();
      runFor(sim, seconds);
      long cpu = threads.getCurrentThreadCpuTime() - cpuStart;
      long virtual = sim.timeNanos() - virtualStart;
      double rtf = virtual / (double) (time.nanoTime() - realStart);
      double atomSteps = (double) atoms * virtual / step.toNanos();
      out.printf(
          java.util.Locale.ROOT,
          "sim name=rtf atoms=%d step_ms=%s rtf=%.3f legs=%s cpu_rtf=%.3f us_per_atom_step=%.3f%n",
          atoms,
          stepMs,
          rtf,
          legs.name().toLowerCase(java.util.Locale.ROOT),
          virtual / (double) cpu,
          cpu / 1e3 / atomSteps);
    }
  }

  /** Runs control cycles until {@code seconds} of real time have passed (at least one cycle). */
  private void runFor(Simulation sim, double seconds) {
    long end = time.nanoTime() + (long) (seconds * 1e9);
    do {
      sim.runCycle();
    } while (time.nanoTime() < end);
  }

  /** Reads the body's sensors and swings the three upper legs of the tripod. */
  private static Controller swing(int id) {
    return (AtomBody body, long cycle) -> {
      double energy = body.sensors().energy();
      double a = energy > 0 ? 0.4 * Math.sin(cycle * 0.05 + id) : 0;
      body.setLegTarget(Leg.PX, a, 0);
      body.setLegTarget(Leg.PY, 0, a);
      body.setLegTarget(Leg.PZ, a, -a);
    };
  }
}

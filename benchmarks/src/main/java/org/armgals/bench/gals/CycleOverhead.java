package org.armgals.bench.gals;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.BehaviorModule;
import org.armgals.maam.Inputs;
import org.armgals.maam.Outputs;
import org.armgals.maam.Perceptor;
import org.armgals.maam.Port;
import org.armgals.maam.Reactor;
import org.armgals.maam.Schema;
import org.armgals.maam.Signal;
import org.armgals.maam.spi.ActuatorKey;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.SensorKey;
import org.jspecify.annotations.Nullable;

/**
 * {@code gals name=cycle-overhead ratio=<x> min=<a> max=<b> rounds=<n> robot_ns=<r> loop_ns=<l>}:
 * the time of a robot's {@link AbstractRobot#cycle} of 50 modules (10 schemas, each a chain of a
 * perceptor, three reactors and an actuator) against a hand-written loop calling the same module
 * objects in the same order through one-field slots.
 *
 * <p>What it measures is MAAM's own cost per cycle, maam-framework's compiled plan: the robot is
 * stepped by hand on the measuring thread, not released by an island, so no arm-gals code (no
 * island, release, entity or trace) runs in it. Both sides call the same modules, which allocate
 * their signals and read a body, and both empty the modules' outputs in each cycle before they run;
 * the robot adds, per module, the dispatch on its kind, the lookup of its ports, the check of an
 * emitted signal's type and the connectors' bookkeeping, and per cycle its clock reading.
 *
 * <p>Rounds of {@value #CYCLES} cycles alternate the two, robot first, timed in the measuring
 * thread's CPU time. The first rounds warm up, until both {@value #WARMUP_ROUNDS} rounds and {@code
 * -Dgals.cycle.warmup-seconds} (default 5) of wall time have passed: the JIT compiles late on a
 * busy machine, and the hand-written loop reaches its compiled speed after the robot; then {@value
 * #ROUNDS} rounds are measured. {@code ratio} is the median of their ratios, {@code min} and {@code
 * max} the extremes, {@code robot_ns} and {@code loop_ns} the median CPU nanoseconds of one cycle
 * of each. The ratios of every measured round go to standard error.
 */
final class CycleOverhead {

  private static final int CHAINS = 10;
  private static final int WARMUP_ROUNDS = 15;
  private static final int ROUNDS = 15;
  private static final int CYCLES = 20_000;

  private CycleOverhead() {}

  static void run() throws Exception {
    ConstantBody body = new ConstantBody();
    List<List<BehaviorModule>> chains = new ArrayList<>();
    AbstractRobot robot = robot("bench", body, chains);
    HandLoop loop = new HandLoop(chains, body);
    ThreadMXBean threads = ManagementFactory.getThreadMXBean();
    long[] pair = new long[2];
    int warmupSeconds = Integer.getInteger("gals.cycle.warmup-seconds", 5);
    if (warmupSeconds < 0) {
      throw new IllegalArgumentException(
          "gals.cycle.warmup-seconds must be >= 0, was " + warmupSeconds);
    }
    long warmupEnd = System.nanoTime() + warmupSeconds * 1_000_000_000L;
    int warmups = 0;
    while (warmups < WARMUP_ROUNDS || System.nanoTime() - warmupEnd < 0) {
      round(robot, loop, threads, pair);
      warmups++;
    }
    double[] ratios = new double[ROUNDS];
    double[] robotNs = new double[ROUNDS];
    double[] loopNs = new double[ROUNDS];
    StringBuilder each = new StringBuilder();
    for (int r = 0; r < ROUNDS; r++) {
      round(robot, loop, threads, pair);
      ratios[r] = (double) pair[0] / pair[1];
      robotNs[r] = (double) pair[0] / CYCLES;
      loopNs[r] = (double) pair[1] / CYCLES;
      each.append(String.format(Locale.ROOT, " %.2f", ratios[r]));
    }
    if (body.commands == 0 || robot.errors() != 0) {
      throw new IllegalStateException("the modules did not run: " + robot.errors() + " errors");
    }
    System.err.printf(
        Locale.ROOT,
        "# cycle-overhead: AbstractRobot.cycle() stepped by hand (maam-framework's plan, no island)"
            + " against a hand-written loop over the same %d modules, in the measuring thread's CPU"
            + " time; %d warm-up rounds, then %d rounds of %d cycles, ratios:%s%n",
        CHAINS * 5,
        warmups,
        ROUNDS,
        CYCLES,
        each);
    double[] sorted = ratios.clone();
    Arrays.sort(sorted);
    System.out.printf(
        Locale.ROOT,
        "gals name=cycle-overhead ratio=%.2f min=%.2f max=%.2f rounds=%d robot_ns=%.0f"
            + " loop_ns=%.0f%n",
        median(ratios),
        sorted[0],
        sorted[sorted.length - 1],
        ROUNDS,
        median(robotNs),
        median(loopNs));
  }

  /**
   * A robot called {@code name} of 50 modules on {@code body}, in 10 schemas of 5 modules each;
   * each schema's modules are added to {@code chains} in order. A failure of a module is thrown out
   * of its cycle.
   */
  static AbstractRobot robot(String name, Body body, List<List<BehaviorModule>> chains) {
    BenchRobot robot = new BenchRobot(name, body);
    for (int c = 0; c < CHAINS; c++) {
      List<BehaviorModule> chain =
          List.of(
              new BenchModules.Sense("c" + c + ".sense"),
              new BenchModules.Gain("c" + c + ".g1", 0.9),
              new BenchModules.Gain("c" + c + ".g2", 1.1),
              new BenchModules.Gain("c" + c + ".g3", 0.7),
              new BenchModules.Drive("c" + c + ".drive"));
      Schema.Builder schema = Schema.builder("chain" + c);
      chain.forEach(schema::add);
      for (int i = 0; i + 1 < chain.size(); i++) {
        schema.wire(chain.get(i), BenchModules.OUT, chain.get(i + 1), BenchModules.IN);
      }
      robot.addSchema(schema.build());
      chains.add(chain);
    }
    return robot;
  }

  /**
   * One round: {@value #CYCLES} cycles of the robot, then as many of the loop; their thread CPU
   * times in {@code pair}. Paired per round: on a shared machine, time spent descheduled would
   * otherwise land on whichever of the two happened to be running.
   */
  private static void round(AbstractRobot robot, HandLoop loop, ThreadMXBean threads, long[] pair)
      throws Exception {
    long start = threads.getCurrentThreadCpuTime();
    for (int i = 0; i < CYCLES; i++) {
      robot.cycle();
    }
    long middle = threads.getCurrentThreadCpuTime();
    for (int i = 0; i < CYCLES; i++) {
      loop.cycle();
    }
    long end = threads.getCurrentThreadCpuTime();
    pair[0] = middle - start;
    pair[1] = end - middle;
  }

  private static double median(double[] values) {
    double[] sorted = values.clone();
    Arrays.sort(sorted);
    int n = sorted.length;
    return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
  }

  /** The robot. */
  private static final class BenchRobot extends AbstractRobot {
    BenchRobot(String name, Body body) {
      super(name, body, () -> 0L);
      setErrorHandler(
          (robot, where, error) -> {
            throw new IllegalStateException(where, error);
          });
    }
  }

  /** The same modules, called in the same order, each chain through one-field slots. */
  private static final class HandLoop {
    private final BehaviorModule[][] chains;
    private final Slot[][] slots;
    private final Body body;

    HandLoop(List<List<BehaviorModule>> chains, Body body) {
      this.body = body;
      this.chains = new BehaviorModule[chains.size()][];
      this.slots = new Slot[chains.size()][];
      for (int c = 0; c < chains.size(); c++) {
        this.chains[c] = chains.get(c).toArray(new BehaviorModule[0]);
        this.slots[c] = new Slot[this.chains[c].length];
        for (int i = 0; i < this.slots[c].length; i++) {
          this.slots[c][i] = new Slot();
        }
      }
    }

    void cycle() throws Exception {
      for (int c = 0; c < chains.length; c++) {
        BehaviorModule[] chain = chains[c];
        Slot[] slot = slots[c];
        for (Slot s : slot) {
          s.value = null;
        }
        ((Perceptor) chain[0]).perceive(body, slot[0]);
        ((Reactor) chain[1]).react(slot[0], slot[1]);
        ((Reactor) chain[2]).react(slot[1], slot[2]);
        ((Reactor) chain[3]).react(slot[2], slot[3]);
        ((org.armgals.maam.Actuator) chain[4]).act(slot[3], body);
      }
      body.endCycle();
    }
  }

  /** One signal: what the previous module emitted; the side input reads nothing. */
  private static final class Slot implements Inputs, Outputs {
    @Nullable Signal value;

    @Override
    @SuppressWarnings("unchecked")
    public <S extends Signal> @Nullable S get(Port<S> port) {
      return port == BenchModules.IN ? (S) value : null;
    }

    @Override
    public <S extends Signal> void emit(Port<S> port, S signal) {
      value = signal;
    }
  }

  /** A range sensor that always reads 3 m, and a motor that counts its commands. */
  static final class ConstantBody implements Body {
    long commands;
    double last;

    @Override
    public String id() {
      return "bench";
    }

    @Override
    public Set<SensorKey<?>> sensors() {
      return Set.of(BenchModules.SENSOR);
    }

    @Override
    public Set<ActuatorKey<?>> actuators() {
      return Set.of(BenchModules.MOTOR);
    }

    @Override
    public <T> T read(SensorKey<T> sensor) {
      return sensor.cast(3.0);
    }

    @Override
    public <T> void command(ActuatorKey<T> actuator, T value) {
      commands++;
      last = (Double) value;
    }
  }
}

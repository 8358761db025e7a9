package org.armgals.bench.gals;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import org.armgals.active.TimeSource;
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
 * {@code gals name=cycle-overhead ratio=<x>}: the time of a robot's {@link AbstractRobot#cycle} of
 * 50 modules (10 schemas, each a chain of a perceptor, three reactors and an actuator) against a
 * hand-written loop calling the same module objects in the same order through one-field slots.
 * Rounds alternate the two; the ratio is of the medians.
 */
final class CycleOverhead {

  private static final int CHAINS = 10;
  private static final int ROUNDS = 15;
  private static final int CYCLES = 20_000;

  private CycleOverhead() {}

  static void run() throws Exception {
    TimeSource time = TimeSource.system();
    ConstantBody body = new ConstantBody();
    BenchRobot robot = new BenchRobot(body);
    List<List<BehaviorModule>> chains = new ArrayList<>();
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
    HandLoop loop = new HandLoop(chains, body);
    long[] robotNanos = new long[ROUNDS];
    long[] loopNanos = new long[ROUNDS];
    for (int round = 0; round < ROUNDS; round++) {
      long start = time.nanoTime();
      for (int i = 0; i < CYCLES; i++) {
        robot.cycle();
      }
      long middle = time.nanoTime();
      for (int i = 0; i < CYCLES; i++) {
        loop.cycle();
      }
      robotNanos[round] = middle - start;
      loopNanos[round] = time.nanoTime() - middle;
    }
    if (body.commands == 0 || robot.errors() != 0) {
      throw new IllegalStateException("the modules did not run: " + robot.errors() + " errors");
    }
    Arrays.sort(robotNanos);
    Arrays.sort(loopNanos);
    double robotPerCycle = (double) robotNanos[ROUNDS / 2] / CYCLES;
    double loopPerCycle = (double) loopNanos[ROUNDS / 2] / CYCLES;
    System.err.printf(
        "# cycle-overhead: %d modules, robot %.0f ns/cycle, hand-written loop %.0f ns/cycle%n",
        CHAINS * 5, robotPerCycle, loopPerCycle);
    System.out.printf("gals name=cycle-overhead ratio=%.2f%n", robotPerCycle / loopPerCycle);
  }

  /** The robot. */
  private static final class BenchRobot extends AbstractRobot {
    BenchRobot(Body body) {
      super("bench", body, () -> 0L);
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
  private static final class ConstantBody implements Body {
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

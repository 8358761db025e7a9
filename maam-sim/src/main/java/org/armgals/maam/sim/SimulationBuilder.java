package org.armgals.maam.sim;

import static java.util.Objects.requireNonNull;

import java.io.Writer;
import java.time.Duration;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.IntFunction;
import org.armgals.maam.sim.spi.Controller;
import org.armgals.maam.sim.spi.Pacer;
import org.jspecify.annotations.Nullable;

/** Configures and builds a {@link Simulation}; checks everything in {@link #build()}. */
public final class SimulationBuilder {

  final Scene scene;
  long seed = 1;
  long stepNanos = 1_000_000;
  long periodNanos = 10_000_000;
  long messageDelayNanos = 0;
  double packetLoss = 0;
  IntFunction<Controller> controllers = id -> Controller.idle();
  final Map<Integer, Controller> controllerById = new HashMap<>();
  Pacer pacer = Pacer.asFastAsPossible();
  @Nullable Writer trace;
  final Map<String, String> traceAttributes = new LinkedHashMap<>();
  LegDynamics legDynamics = LegDynamics.KINEMATIC;
  int threads = 1;

  SimulationBuilder(Scene scene) {
    this.scene = requireNonNull(scene, "scene");
  }

  /** The seed of every random draw (message loss); default 1. */
  public SimulationBuilder seed(long seed) {
    this.seed = seed;
    return this;
  }

  /** The fixed physics step; default 1 ms. */
  public SimulationBuilder physicsStep(Duration step) {
    this.stepNanos = requireNonNull(step, "step").toNanos();
    return this;
  }

  /** The control period (the robot's cycle), a whole number of physics steps; default 10 ms. */
  public SimulationBuilder controlPeriod(Duration period) {
    this.periodNanos = requireNonNull(period, "period").toNanos();
    return this;
  }

  /** How long a neighbour message takes; default zero (it arrives at the next cycle). */
  public SimulationBuilder messageDelay(Duration delay) {
    this.messageDelayNanos = requireNonNull(delay, "delay").toNanos();
    return this;
  }

  /** The probability, in [0, 1], that a neighbour message is lost; default 0. */
  public SimulationBuilder packetLoss(double probability) {
    this.packetLoss = probability;
    return this;
  }

  /** The controller of every atom without one of its own; default {@link Controller#idle()}. */
  public SimulationBuilder controllers(IntFunction<Controller> byId) {
    this.controllers = requireNonNull(byId, "byId");
    return this;
  }

  /** The controller of atom {@code id}. */
  public SimulationBuilder controller(int id, Controller controller) {
    controllerById.put(id, requireNonNull(controller, "controller"));
    return this;
  }

  /**
   * How legs move: {@link LegDynamics#KINEMATIC} (the default: one body per atom, several times
   * faster; the example robots are tuned for it) or {@link LegDynamics#JOINTED} (each leg a body on
   * a universal joint).
   */
  public SimulationBuilder legDynamics(LegDynamics dynamics) {
    this.legDynamics = requireNonNull(dynamics, "dynamics");
    return this;
  }

  /**
   * How many threads a physics step's work on the atoms is spread over, the calling thread among
   * them, and the controllers too if all are {@link Controller#confined confined}; default 1. The
   * trace is the same, bit for bit, on any number; more than one pays off from a few hundred atoms
   * on, on as many free cores.
   */
  public SimulationBuilder threads(int threads) {
    if (threads < 1) {
      throw new IllegalArgumentException(threads + " threads: expected at least 1");
    }
    this.threads = threads;
    return this;
  }

  /** How virtual time is held to real time; default {@link Pacer#asFastAsPossible()}. */
  public SimulationBuilder pacer(Pacer pacer) {
    this.pacer = requireNonNull(pacer, "pacer");
    return this;
  }

  /**
   * Where the trace goes: one JSON line per control cycle (format in docs/simulator.md). The
   * simulation flushes it on {@link Simulation#close()} but does not close it.
   */
  public SimulationBuilder trace(Writer trace) {
    this.trace = requireNonNull(trace, "trace");
    return this;
  }

  /**
   * Adds {@code name: value} to the trace's header, under {@code "attributes"}, in the order added:
   * what a tool needs to know about the run beyond the scene and the seed (the robot that ran, its
   * options), e.g. to replay it.
   *
   * @throws IllegalArgumentException if {@code name} is blank or already added
   */
  public SimulationBuilder traceAttribute(String name, String value) {
    requireNonNull(name, "name");
    requireNonNull(value, "value");
    if (name.isBlank()) {
      throw new IllegalArgumentException("trace attribute name is blank: expected a word");
    }
    if (traceAttributes.putIfAbsent(name, value) != null) {
      throw new IllegalArgumentException("trace attribute '" + name + "' is already set");
    }
    return this;
  }

  /** Checks the configuration and builds the simulation, its atoms at their scene poses. */
  public Simulation build() {
    if (stepNanos <= 0) {
      throw new IllegalArgumentException("physics step " + stepNanos + " ns: expected > 0");
    }
    if (periodNanos <= 0 || periodNanos % stepNanos != 0) {
      throw new IllegalArgumentException(
          "control period "
              + periodNanos
              + " ns: expected a positive multiple of the physics step, "
              + stepNanos
              + " ns");
    }
    if (messageDelayNanos < 0) {
      throw new IllegalArgumentException(
          "message delay " + messageDelayNanos + " ns: expected >= 0");
    }
    checkProbability(packetLoss);
    for (int id : controllerById.keySet()) {
      if (scene.atoms().stream().noneMatch(p -> p.id() == id)) {
        throw new IllegalArgumentException(
            "controller for atom " + id + ", which is not in scene '" + scene.name() + "'");
      }
    }
    return new SimulationImpl(this);
  }

  static void checkProbability(double p) {
    if (!(p >= 0 && p <= 1)) {
      throw new IllegalArgumentException("packet loss " + p + " is not a probability in [0, 1]");
    }
  }
}

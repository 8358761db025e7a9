package org.armgals.maam.sim;

import java.time.Duration;
import java.util.List;
import org.armgals.maam.sim.spi.Controller;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;

/**
 * A running scene: atoms, their controllers and the world, stepped in virtual time. One control
 * cycle ({@link #runCycle()}) reads every atom's sensors, delivers the neighbour messages that are
 * due, binds the locked tips that are within tolerance, runs every controller in the order of atom
 * ids, runs the physics for one control period in fixed steps, then records the cycle (its sensor
 * readings and its events) in the trace. Same scene, seed, controllers and fault calls give the
 * same trace, bit for bit.
 *
 * <p>Concurrency: a simulation is confined to the thread that calls it; it is not thread-safe.
 * Simulations on different threads may run at once (the engine's one global, its random seed, is
 * swapped under a lock around each step).
 */
public interface Simulation extends AutoCloseable {

  /** A builder for a simulation of {@code scene}. */
  static SimulationBuilder builder(Scene scene) {
    return new SimulationBuilder(scene);
  }

  /** The scene it runs. */
  Scene scene();

  /** The ids of its atoms, ascending. */
  List<Integer> atomIds();

  /**
   * What atom {@code id} sensed at the start of the current control cycle, with where it is in the
   * world (ground truth): for traces, pictures, tests and a robot's odometer, never for its
   * controller's decisions (the {@link #body} reads what an atom can sense).
   */
  AtomSensors sensors(int id);

  /**
   * Atom {@code id} as the MAAM framework's {@link Body}: the one way to drive an atom. Its body id
   * is {@code "a" + id}; its sensors read the values of the current cycle and its actuators take
   * the framework's {@code Atom} keys (leg angles as {@link org.armgals.maam.spi.LegAngles}); see
   * docs/simulator.md for the mapping.
   *
   * <p>It is one instance for the simulation's life, and the very one the atom's {@link Controller}
   * is handed each cycle: a robot is built on it before the first cycle (a kernel entity exists
   * before the cycles that run it), and its controller steps the robot, e.g. {@link
   * Controller#driving Controller.driving(sim.body(id), robot::cycle)}, which checks that it is
   * handed the body the robot was built on.
   */
  Body body(int id);

  /**
   * Replaces the controller of atom {@code id} from the next control cycle on; it is handed {@link
   * #body body(id)}.
   */
  void setController(int id, Controller controller);

  /** Runs one control cycle and the physics of one control period. */
  void runCycle();

  /** Runs {@code cycles} control cycles. */
  default void runCycles(int cycles) {
    if (cycles < 0) {
      throw new IllegalArgumentException("cycles " + cycles + " is negative");
    }
    for (int i = 0; i < cycles; i++) {
      runCycle();
    }
  }

  /** Runs control cycles until at least {@code duration} of virtual time has passed. */
  default void runFor(Duration duration) {
    long end = timeNanos() + duration.toNanos();
    while (timeNanos() < end) {
      runCycle();
    }
  }

  /** The number of control cycles run so far. */
  long cycle();

  /** The virtual time (ns since the start). */
  long timeNanos();

  /** The events of the last control cycle and its physics, in order. */
  List<SimEvent> lastEvents();

  /**
   * Applies {@code force} (N, world frame) to atom {@code id}'s kernel during every physics step of
   * the next control period: a push, for experiments and tests.
   */
  void push(int id, Vec3 force);

  /** Fails atom {@code id}: its motors stop, it senses nothing and sends nothing. */
  void failAtom(int id);

  /**
   * Fails {@code leg} of atom {@code id}: its motors stop, it senses nothing and sends nothing; its
   * binding, a mechanical latch, holds.
   */
  void failLeg(int id, Leg leg);

  /** Sets the probability, in [0, 1], that a neighbour message is lost. */
  void setPacketLoss(double probability);

  /** Notes something the meta level saw or did about atom {@code id}, for the trace. */
  void note(int id, String text);

  /** Flushes the trace and releases the physics. */
  @Override
  void close();
}

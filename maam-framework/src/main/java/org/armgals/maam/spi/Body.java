package org.armgals.maam.spi;

import java.util.Set;

/**
 * What a robot senses and drives: a set of named, typed sensors and actuators (the simulator
 * implements it for MAAM atoms; {@code org.armgals.testkit.maam.FakeBody} of armgals-testkit-maam
 * is the test double; a real robot could too). The names and types of an atom's are in {@link
 * Atom}.
 *
 * <p>Concurrency contract: a robot calls {@link #read}, {@link #command} and {@link #endCycle} only
 * from the thread running its cycle, one cycle at a time. A body changes the values its sensors
 * read only between two cycles of its robot (a simulator steps its world between them), so every
 * module of one cycle sees the same snapshot; the hand-over between the body's thread and the
 * robot's must be a happens-before edge (the robot's clock provides one).
 */
public interface Body {

  /** The body's identity; for an atom, the id its neighbours see in their binding sensors. */
  String id();

  /** The sensors of this body; fixed for its lifetime. */
  Set<SensorKey<?>> sensors();

  /** The actuators of this body; fixed for its lifetime. */
  Set<ActuatorKey<?>> actuators();

  /**
   * The value {@code sensor} reads in the current cycle.
   *
   * @throws IllegalArgumentException the body has no such sensor
   */
  <T> T read(SensorKey<T> sensor);

  /**
   * Sends {@code value} to {@code actuator}. Commands are delivered in order: a body keeps the last
   * command of a level actuator (an angle target, a torque) and carries out each command of an
   * event actuator (bind, unbind, a message) once.
   *
   * @throws IllegalArgumentException the body has no such actuator, or {@code value} is not of its
   *     type
   */
  <T> void command(ActuatorKey<T> actuator, T value);

  /**
   * Called by the robot after the last module of a cycle: a body may send the cycle's commands as
   * one batch here. Does nothing by default.
   */
  default void endCycle() {}
}

package org.armgals.maam.sim;

import java.util.List;
import org.armgals.maam.spi.Leg;

/**
 * One atom's body as its controller sees it: sensors read at the start of the current control
 * cycle, and actuators whose commands take effect for the physics steps of that cycle.
 *
 * <p>Concurrency: a body is used only by the thread running the simulation, from within its
 * controller's cycle (or between cycles); it is not thread-safe.
 */
public interface AtomBody {

  /** The atom's id. */
  int id();

  /** The sensors, as read at the start of the current control cycle. */
  AtomSensors sensors();

  /**
   * Drives {@code leg} towards the angles {@code (angle1, angle2)} (rad) with its position servo,
   * within its torque and speed limits. A target outside the cone is brought back onto its edge
   * (same direction, smaller tilt).
   */
  void setLegTarget(Leg leg, double angle1, double angle2);

  /**
   * Limits the torque of {@code leg}'s motors to {@code torque} (N·m, >= 0); the atom's {@code
   * maxTorque} stays the ceiling.
   */
  void setTorqueLimit(Leg leg, double torque);

  /** Switches {@code leg}'s motors off: it hangs limp until the next target. */
  void relax(Leg leg);

  /**
   * Locks {@code leg}'s connector: it binds to the first locked tip that comes within the distance
   * and alignment tolerances (at a control cycle), and stays bound until {@link #unbind} or until
   * the binding breaks.
   */
  void bind(Leg leg);

  /** Unlocks {@code leg}'s connector, releasing its binding if it has one. */
  void unbind(Leg leg);

  /**
   * Sends {@code payload} to the neighbour bound at {@code leg}. It arrives after the simulation's
   * message delay unless lost. Returns false, sending nothing, if the leg is not bound or the atom
   * has failed.
   */
  boolean send(Leg leg, String payload);

  /** The messages that arrived at the start of this control cycle, oldest first. */
  List<ReceivedMessage> receive();
}

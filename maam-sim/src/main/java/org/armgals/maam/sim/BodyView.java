package org.armgals.maam.sim;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.List;
import org.armgals.maam.spi.Leg;

/**
 * An atom's sensors and actuators in the physics' terms (a leg's target is the joint's two axis
 * angles): what {@link SimBody}, the public face of an atom, drives, and what the simulator's own
 * tests drive directly. Confined to the simulation's thread, but while {@linkplain
 * org.armgals.maam.sim.spi.Controller#confined confined controllers} run on the lanes: then its
 * atom's controller alone drives it, on its lane.
 */
final class BodyView {

  private final SimulationImpl simulation;
  final AtomModel model;

  /** The readings of the current cycle. */
  AtomSensors sensors;

  /**
   * The joint's two angles of each leg, as read with {@link #sensors} ({@code 2 * ordinal}, {@code
   * 2 * ordinal + 1}): what the trace records, exactly as the physics had them.
   */
  final double[] joints = new double[2 * Leg.values().length];

  /** This atom as the framework's body: the one instance its controller is handed. */
  final SimBody body;

  BodyView(SimulationImpl simulation, AtomModel model) {
    this.simulation = simulation;
    this.model = model;
    this.sensors = simulation.sense(model, joints);
    this.body = new SimBody(this);
  }

  /** Limits {@code leg}'s motors to {@code torque} (N·m); the atom's maximum stays the ceiling. */
  void setTorqueLimit(Leg leg, double torque) {
    requireNonNull(leg, "leg");
    if (!(torque >= 0) || Double.isInfinite(torque)) {
      throw new IllegalArgumentException(
          "torque limit " + torque + " N·m: expected a finite number >= 0");
    }
    model.leg(leg).setTorqueLimit(Math.min(torque, model.params.maxTorque()));
  }

  int id() {
    return model.id;
  }

  AtomSensors sensors() {
    return sensors;
  }

  /**
   * Drives {@code leg} towards the joint angles {@code (angle1, angle2)} (rad) with its position
   * servo, within its torque and speed limits; a target outside the cone is brought back onto its
   * edge (same direction, smaller tilt).
   */
  void setLegTarget(Leg leg, double angle1, double angle2) {
    requireNonNull(leg, "leg");
    if (!Double.isFinite(angle1) || !Double.isFinite(angle2)) {
      throw new IllegalArgumentException(
          "leg target (" + angle1 + ", " + angle2 + ") rad: expected finite angles");
    }
    model.leg(leg).setTarget(angle1, angle2);
  }

  /** Switches {@code leg}'s motors off: it hangs limp until the next target. */
  void relax(Leg leg) {
    model.leg(requireNonNull(leg, "leg")).relax();
  }

  /** Locks {@code leg}'s connector: it binds to the first locked tip within tolerance. */
  void bind(Leg leg) {
    LegModel locked = model.leg(requireNonNull(leg, "leg"));
    if (simulation.controllingOnLanes()) {
      deferred.add(() -> locked.locked = true);
      return;
    }
    locked.locked = true;
  }

  /** Unlocks {@code leg}'s connector, releasing its binding if it has one. */
  void unbind(Leg leg) {
    LegModel unlocked = model.leg(requireNonNull(leg, "leg"));
    if (simulation.controllingOnLanes()) {
      deferred.add(() -> simulation.unbind(unlocked));
      return;
    }
    simulation.unbind(unlocked);
  }

  /**
   * Sends {@code payload} through {@code leg}'s binding; false if not bound or failed. From a
   * controller on a lane the message goes after the pass, and the answer is as of the pass's start
   * (a binding released in the same cycle is not seen).
   */
  boolean send(Leg leg, String payload) {
    requireNonNull(payload, "payload");
    LegModel from = model.leg(requireNonNull(leg, "leg"));
    if (simulation.controllingOnLanes()) {
      deferred.add(() -> simulation.send(from, payload));
      return SimulationImpl.canSend(from);
    }
    return simulation.send(from, payload);
  }

  /**
   * The binds, unbinds and sends of this atom's controller while it ran on a lane, in its order:
   * they write what other atoms read, so they wait for the pass's end (see {@link
   * org.armgals.maam.sim.spi.Controller#confined}).
   */
  private final List<Runnable> deferred = new ArrayList<>(0);

  /** Carries out the {@link #deferred} commands, in order, on the simulation's thread. */
  void runDeferred() {
    if (!deferred.isEmpty()) {
      for (Runnable command : deferred) {
        command.run();
      }
      deferred.clear();
    }
  }

  /** Drops the {@link #deferred} commands of a pass that failed. */
  void dropDeferred() {
    deferred.clear();
  }

  /** The messages that arrived at the start of this control cycle, oldest first. */
  List<ReceivedMessage> receive() {
    return List.copyOf(model.inbox);
  }
}

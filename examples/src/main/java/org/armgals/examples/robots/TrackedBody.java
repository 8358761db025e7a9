package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.util.LinkedHashSet;
import java.util.Set;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.sim.Vec3;
import org.armgals.maam.sim.spi.Controller;
import org.armgals.maam.spi.ActuatorKey;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.SensorKey;

/**
 * A simulated atom's framework body with one more sensor, {@link #POSITION}: where the kernel is on
 * the ground plane, as an odometer or a beacon would tell a real atom, which the simulator gives as
 * ground truth. The framework's body SPI has no position sensor (an atom does not know where it is
 * in the world); the example robots whose meta level watches their progress read this one. Used on
 * the simulation's thread, like the body it wraps.
 */
final class TrackedBody implements Body {

  /** Where the atom is on the ground plane. */
  static final SensorKey<Place> POSITION = SensorKey.of("position", Place.class);

  /**
   * A point of the ground plane, metres.
   *
   * @param x along the world's x axis
   * @param y along the world's y axis
   */
  record Place(double x, double y) {}

  private final Simulation sim;
  private final int atom;
  private final Body body;
  private final Set<SensorKey<?>> sensors;

  private TrackedBody(Simulation sim, int atom) {
    this.sim = sim;
    this.atom = atom;
    this.body = sim.body(atom);
    Set<SensorKey<?>> all = new LinkedHashSet<>(body.sensors());
    all.add(POSITION);
    this.sensors = Set.copyOf(all);
  }

  /** The body of {@code sim}'s atom {@code id}, with a position sensor. */
  static TrackedBody of(Simulation sim, int id) {
    requireNonNull(sim, "sim");
    return new TrackedBody(sim, id);
  }

  /**
   * The controller of the atom whose robot is built on this body: each cycle, {@code step} steps
   * the robot, once the simulation is seen to hand the controller the body this one wraps.
   */
  Controller driving(Runnable step) {
    return Controller.driving(body, step);
  }

  @Override
  public String id() {
    return body.id();
  }

  @Override
  public Set<SensorKey<?>> sensors() {
    return sensors;
  }

  @Override
  public Set<ActuatorKey<?>> actuators() {
    return body.actuators();
  }

  @Override
  public <T> T read(SensorKey<T> sensor) {
    if (POSITION.equals(sensor)) {
      Vec3 p = sim.sensors(atom).position();
      return sensor.cast(new Place(p.x(), p.y()));
    }
    return body.read(sensor);
  }

  @Override
  public <T> void command(ActuatorKey<T> actuator, T value) {
    body.command(actuator, value);
  }

  @Override
  public void endCycle() {
    body.endCycle();
  }
}

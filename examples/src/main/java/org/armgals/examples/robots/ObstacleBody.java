package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.util.HashSet;
import java.util.Set;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.spi.ActuatorKey;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.SensorKey;

/**
 * A simulated atom's body with one more sensor, {@link #POSITION}: odometry along the path, which a
 * real molecule would get from a beacon or from counting its strides, and which the simulator gives
 * as ground truth. Everything else is the simulator's body of the atom.
 */
final class ObstacleBody implements Body {
  /** Where the atom's kernel is along x (m). */
  static final SensorKey<Double> POSITION = SensorKey.of("position.x", Double.class);

  private final Body body;
  private final Simulation sim;
  private final int id;
  private final Set<SensorKey<?>> sensors;

  ObstacleBody(Simulation sim, int id) {
    this.sim = requireNonNull(sim, "sim");
    this.id = id;
    this.body = sim.body(id);
    Set<SensorKey<?>> all = new HashSet<>(body.sensors());
    all.add(POSITION);
    this.sensors = Set.copyOf(all);
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
    if (sensor.equals(POSITION)) {
      return sensor.cast(sim.atom(id).sensors().position().x());
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

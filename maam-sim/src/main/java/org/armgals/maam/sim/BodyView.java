package org.armgals.maam.sim;

import static java.util.Objects.requireNonNull;

import java.util.List;
import org.armgals.maam.spi.Leg;
import org.jspecify.annotations.Nullable;

/** An atom's {@link AtomBody}: the controller's view of an {@link AtomModel}. */
final class BodyView implements AtomBody {

  private final SimulationImpl simulation;
  final AtomModel model;
  AtomSensors sensors;

  BodyView(SimulationImpl simulation, AtomModel model, AtomSensors sensors) {
    this.simulation = simulation;
    this.model = model;
    this.sensors = sensors;
  }

  private @Nullable SimBody spiBody;

  /** This atom as the framework's body SPI sees it (made on first use). */
  SimBody spiBody() {
    SimBody b = spiBody;
    if (b == null) {
      b = new SimBody(this);
      spiBody = b;
    }
    return b;
  }

  @Override
  public void setTorqueLimit(Leg leg, double torque) {
    requireNonNull(leg, "leg");
    if (!(torque >= 0) || Double.isInfinite(torque)) {
      throw new IllegalArgumentException(
          "torque limit " + torque + " N·m: expected a finite number >= 0");
    }
    model.leg(leg).torqueLimit = Math.min(torque, model.params.maxTorque());
  }

  @Override
  public int id() {
    return model.id;
  }

  @Override
  public AtomSensors sensors() {
    return sensors;
  }

  @Override
  public void setLegTarget(Leg leg, double angle1, double angle2) {
    requireNonNull(leg, "leg");
    if (!Double.isFinite(angle1) || !Double.isFinite(angle2)) {
      throw new IllegalArgumentException(
          "leg target (" + angle1 + ", " + angle2 + ") rad: expected finite angles");
    }
    model.leg(leg).setTarget(angle1, angle2);
  }

  @Override
  public void relax(Leg leg) {
    model.leg(requireNonNull(leg, "leg")).powered = false;
  }

  @Override
  public void bind(Leg leg) {
    model.leg(requireNonNull(leg, "leg")).locked = true;
  }

  @Override
  public void unbind(Leg leg) {
    simulation.unbind(model.leg(requireNonNull(leg, "leg")));
  }

  @Override
  public boolean send(Leg leg, String payload) {
    requireNonNull(payload, "payload");
    return simulation.send(model.leg(requireNonNull(leg, "leg")), payload);
  }

  @Override
  public List<ReceivedMessage> receive() {
    return List.copyOf(model.inbox);
  }
}

package org.armgals.maam.sim;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.List;

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
  public List<NeighbourMessage> receive() {
    List<NeighbourMessage> received = new ArrayList<>(model.inbox);
    model.inbox.clear();
    return received;
  }
}

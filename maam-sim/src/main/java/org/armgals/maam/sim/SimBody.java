package org.armgals.maam.sim;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.armgals.maam.spi.ActuatorKey;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.BindCommand;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Inbox;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;
import org.armgals.maam.spi.LegBinding;
import org.armgals.maam.spi.NeighbourMessage;
import org.armgals.maam.spi.SensorKey;
import org.armgals.maam.spi.Tilt;

/**
 * A simulated atom as the framework's {@link Body}, the one public way to drive it: reads map onto
 * the cycle's {@link AtomSensors}, commands onto the {@link BodyView}'s actuators. A leg target
 * enters the physics through {@link JointAngles}, as a leg's reading left it.
 */
final class SimBody implements Body {

  /** The atom in the physics' terms. */
  final BodyView atom;

  private final String id;

  SimBody(BodyView atom) {
    this.atom = atom;
    this.id = bodyId(atom.id());
  }

  static String bodyId(int atomId) {
    return "a" + atomId;
  }

  @Override
  public String id() {
    return id;
  }

  @Override
  public Set<SensorKey<?>> sensors() {
    return Atom.sensors();
  }

  @Override
  public Set<ActuatorKey<?>> actuators() {
    return Atom.actuators();
  }

  @Override
  public <T> T read(SensorKey<T> sensor) {
    requireNonNull(sensor, "sensor");
    AtomSensors s = atom.sensors();
    if (sensor.equals(Atom.TILT)) {
      return sensor.cast(tilt(s.orientation()));
    }
    if (sensor.equals(Atom.BATTERY)) {
      return sensor.cast(s.energy());
    }
    if (sensor.equals(Atom.INBOX)) {
      List<NeighbourMessage> messages = new ArrayList<>();
      for (ReceivedMessage m : atom.receive()) {
        messages.add(new NeighbourMessage(m.toLeg(), m.payload()));
      }
      return sensor.cast(new Inbox(messages));
    }
    for (Leg leg : Leg.values()) {
      LegSensors l = s.leg(leg);
      if (sensor.equals(Atom.angles(leg))) {
        return sensor.cast(l.angles());
      }
      if (sensor.equals(Atom.contact(leg))) {
        return sensor.cast(l.tipContact());
      }
      if (sensor.equals(Atom.binding(leg))) {
        LegBinding b =
            l.neighbour().isPresent() && l.neighbourLeg().isPresent()
                ? new LegBinding.Bound(bodyId(l.neighbour().getAsInt()), l.neighbourLeg().get())
                : LegBinding.FREE;
        return sensor.cast(b);
      }
      if (sensor.equals(Atom.proximity(leg))) {
        double range = atom.model.params.proximityRange();
        return sensor.cast(l.proximity() >= range ? Double.POSITIVE_INFINITY : l.proximity());
      }
    }
    throw new IllegalArgumentException(
        "body " + id + " has no sensor '" + sensor.name() + "' of type " + sensor.type().getName());
  }

  @Override
  public <T> void command(ActuatorKey<T> actuator, T value) {
    requireNonNull(actuator, "actuator");
    if (!Atom.actuators().contains(actuator)) {
      throw new IllegalArgumentException(
          "body "
              + id
              + " has no actuator '"
              + actuator.name()
              + "' of type "
              + actuator.type().getName());
    }
    T checked = actuator.cast(value);
    if (actuator.equals(Atom.SEND)) {
      NeighbourMessage m = (NeighbourMessage) checked;
      atom.send(m.leg(), m.payload());
      return;
    }
    for (Leg leg : Leg.values()) {
      if (actuator.equals(Atom.target(leg))) {
        double[] a = JointAngles.of((LegAngles) checked);
        atom.setLegTarget(leg, a[0], a[1]);
        return;
      }
      if (actuator.equals(Atom.torque(leg))) {
        atom.setTorqueLimit(leg, (Double) checked);
        return;
      }
      if (actuator.equals(Atom.bind(leg))) {
        switch ((BindCommand) checked) {
          case BIND -> atom.bind(leg);
          case UNBIND -> atom.unbind(leg);
        }
        return;
      }
    }
    throw new IllegalStateException("actuator '" + actuator.name() + "' is listed but not handled");
  }

  /** Roll and pitch of the kernel (Z-Y-X angles, yaw dropped): 0, 0 when its z axis is up. */
  static Tilt tilt(Quat q) {
    double roll =
        Math.atan2(2 * (q.w() * q.x() + q.y() * q.z()), 1 - 2 * (q.x() * q.x() + q.y() * q.y()));
    double pitch = Math.asin(Math.max(-1, Math.min(1, 2 * (q.w() * q.y() - q.z() * q.x()))));
    return new Tilt(roll, pitch);
  }
}

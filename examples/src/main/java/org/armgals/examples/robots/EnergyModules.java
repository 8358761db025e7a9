package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;
import static org.armgals.examples.robots.EnergySignals.LEVEL;
import static org.armgals.examples.robots.EnergySignals.POSE;
import static org.armgals.examples.robots.EnergySignals.STRIDE;

import java.util.ArrayList;
import java.util.List;
import org.armgals.examples.robots.EnergySignals.EnergyLevel;
import org.armgals.examples.robots.EnergySignals.LegPose;
import org.armgals.examples.robots.EnergySignals.Stride;
import org.armgals.maam.Actuator;
import org.armgals.maam.Inputs;
import org.armgals.maam.Outputs;
import org.armgals.maam.Perceptor;
import org.armgals.maam.Port;
import org.armgals.maam.Reactor;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;

/** The behavior modules of the {@link EnergySaver} robot. */
final class EnergyModules {

  private EnergyModules() {}

  /** Perceptor: the six legs' angles. */
  record LegSensor(String name) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(POSE);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      List<LegAngles> legs = new ArrayList<>();
      for (Leg leg : Leg.values()) {
        legs.add(body.read(Atom.angles(leg)));
      }
      out.emit(POSE, new LegPose(legs));
    }
  }

  /**
   * Reactor: the gait. Its phase advances only while the legs follow (a feedback loop on the sensed
   * angles), so the gait runs as fast as the motors manage with their torque limit. The meta level
   * replaces it by one of another gait ({@code changeModule}): same name, same ports.
   */
  static final class Stepper implements Reactor {
    private final String name;
    private final EnergyGait gait;
    private final double periodSeconds;
    private double phase = EnergyGait.START_PHASE;
    private List<LegAngles> sent = List.of();

    Stepper(String name, EnergyGait gait, double periodSeconds) {
      this.name = requireNonNull(name, "name");
      this.gait = requireNonNull(gait, "gait");
      if (!(periodSeconds > 0)) {
        throw new IllegalArgumentException("period " + periodSeconds + " s: expected > 0");
      }
      this.periodSeconds = periodSeconds;
    }

    EnergyGait gait() {
      return gait;
    }

    @Override
    public String name() {
      return name;
    }

    @Override
    public List<Port<?>> inputs() {
      return List.of(POSE);
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(STRIDE);
    }

    @Override
    public void react(Inputs in, Outputs out) {
      LegPose pose = in.get(POSE);
      if (pose == null || lag(pose) <= EnergyGait.TRACKING_TOLERANCE * gait.stroke()) {
        phase =
            Math.IEEEremainder(phase + 2 * Math.PI * gait.frequency() * periodSeconds, 2 * Math.PI);
      }
      List<LegAngles> targets = new ArrayList<>();
      for (int i = 0; i < Leg.values().length; i++) {
        double azimuth = Math.IEEEremainder(phase + i * EnergyGait.LEG_LAG, 2 * Math.PI);
        targets.add(new LegAngles(gait.stroke(), azimuth));
      }
      sent = List.copyOf(targets);
      out.emit(STRIDE, new Stride(targets, gait.torqueLimit()));
    }

    /** How far, on average, the tips are from where they were last sent (rad). */
    private double lag(LegPose pose) {
      if (sent.isEmpty()) {
        return 0;
      }
      double sum = 0;
      for (int i = 0; i < sent.size(); i++) {
        LegAngles a = sent.get(i);
        LegAngles b = pose.legs().get(i);
        sum +=
            Math.hypot(
                a.elevation() * Math.cos(a.azimuth()) - b.elevation() * Math.cos(b.azimuth()),
                a.elevation() * Math.sin(a.azimuth()) - b.elevation() * Math.sin(b.azimuth()));
      }
      return sum / sent.size();
    }

    @Override
    public String toString() {
      return name + "(" + gait.name() + ")";
    }
  }

  /** Actuator: sends the stride to the legs, and its torque limit to their motors. */
  record LegDrive(String name) implements Actuator {
    @Override
    public List<Port<?>> inputs() {
      return List.of(STRIDE);
    }

    @Override
    public void act(Inputs in, Body body) {
      Stride stride = in.get(STRIDE);
      if (stride == null) {
        return;
      }
      Leg[] legs = Leg.values();
      for (int i = 0; i < legs.length; i++) {
        body.command(Atom.torque(legs[i]), stride.torqueLimit());
        body.command(Atom.target(legs[i]), stride.targets().get(i));
      }
    }
  }

  /**
   * Perceptor: the battery. Every cycle it emits an energy event, the level left; the robot shows
   * it to its meta level ({@link EnergyRobot#observe()}), whose kernel watches the threshold.
   */
  static final class Battery implements Perceptor {
    private final String name;
    private final double capacity;

    Battery(String name, double capacity) {
      this.name = requireNonNull(name, "name");
      if (!(capacity > 0)) {
        throw new IllegalArgumentException("capacity " + capacity + " J: expected > 0");
      }
      this.capacity = capacity;
    }

    @Override
    public String name() {
      return name;
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(LEVEL);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      double joules = body.read(Atom.BATTERY);
      out.emit(LEVEL, new EnergyLevel(joules, joules / capacity));
    }
  }
}

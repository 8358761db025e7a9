package org.armgals.examples.robots;

import static org.armgals.examples.robots.WalkerSignals.COURSE;
import static org.armgals.examples.robots.WalkerSignals.FOOTING;
import static org.armgals.examples.robots.WalkerSignals.JOINTS;
import static org.armgals.examples.robots.WalkerSignals.TARGETS;
import static org.armgals.examples.robots.WalkerSignals.TIPPING;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import org.armgals.examples.robots.WalkerSignals.Course;
import org.armgals.examples.robots.WalkerSignals.Footing;
import org.armgals.examples.robots.WalkerSignals.Joints;
import org.armgals.examples.robots.WalkerSignals.Targets;
import org.armgals.examples.robots.WalkerSignals.Tipping;
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
import org.armgals.maam.spi.Tilt;
import org.jspecify.annotations.Nullable;

/** The walker's behavior modules. */
final class WalkerModules {

  private WalkerModules() {}

  /** Perceptor: where the ground legs point. */
  record ReadJoints(String name) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(JOINTS);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      Map<Leg, LegAngles> angles = new EnumMap<>(Leg.class);
      for (Leg leg : WalkerTuning.GROUND) {
        angles.put(leg, body.read(Atom.angles(leg)));
      }
      out.emit(JOINTS, new Joints(angles));
    }
  }

  /** Perceptor: how many ground legs touch the ground. */
  record Feet(String name) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(FOOTING);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      int down = 0;
      for (Leg leg : WalkerTuning.GROUND) {
        if (body.read(Atom.contact(leg))) {
          down++;
        }
      }
      out.emit(FOOTING, new Footing(down));
    }
  }

  /**
   * Perceptor: emits a stimulus when the atom leans more than {@code limit} radians away from the
   * attitude it had at its first cycle (resting on its tripod), nothing otherwise.
   */
  static final class Lean implements Perceptor {
    private final String name;
    private final double limit;
    private @Nullable Tilt rest;

    Lean(String name, double limit) {
      this.name = name;
      this.limit = limit;
    }

    @Override
    public String name() {
      return name;
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(TIPPING);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      Tilt tilt = body.read(Atom.TILT);
      Tilt reference = rest;
      if (reference == null) {
        rest = tilt;
        return;
      }
      double lean =
          Math.max(
              Math.abs(angle(tilt.roll() - reference.roll())),
              Math.abs(tilt.pitch() - reference.pitch()));
      if (lean > limit) {
        out.emit(TIPPING, new Tipping(lean));
      }
    }

    private static double angle(double a) {
      return Math.atan2(Math.sin(a), Math.cos(a));
    }
  }

  /** Perceptor: where the walker is on the ground. */
  record Odometer(String name) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(COURSE);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      TrackedBody.Place p = body.read(TrackedBody.POSITION);
      out.emit(COURSE, new Course(p.x(), p.y()));
    }
  }

  /**
   * Reactor, the gait's phase generator and stepping reflex: each ground leg's tip circles its
   * cone, the three a third of a turn apart, so that the atom rocks and shuffles on its tips. A
   * closed loop: the phase goes on only while the legs keep up with their targets and at least two
   * feet are down; otherwise it waits for them (a slower leg, or a foot off the ground, slows the
   * gait instead of tearing it apart).
   */
  static final class Gait implements Reactor {
    private final String name;
    private final double cycleSeconds;
    private double phase;
    private @Nullable Map<Leg, LegAngles> last;

    Gait(String name, double cycleSeconds) {
      this.name = name;
      this.cycleSeconds = cycleSeconds;
    }

    @Override
    public String name() {
      return name;
    }

    @Override
    public List<Port<?>> inputs() {
      return List.of(JOINTS, FOOTING);
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(TARGETS);
    }

    @Override
    public void react(Inputs in, Outputs out) {
      Joints joints = in.get(JOINTS);
      Footing footing = in.get(FOOTING);
      boolean keepingUp =
          last == null || (joints != null && lag(joints.angles()) < WalkerTuning.TRACKING);
      boolean standing = footing != null && footing.legsDown() >= 2;
      if (keepingUp && standing) {
        phase += cycleSeconds * WalkerTuning.FREQUENCY;
        phase -= Math.floor(phase);
      }
      Map<Leg, LegAngles> targets = new EnumMap<>(Leg.class);
      for (int i = 0; i < WalkerTuning.GROUND.size(); i++) {
        double turn = WalkerTuning.TURN * 2 * Math.PI * (phase + WalkerTuning.OFFSETS[i]);
        double azimuth = Math.atan2(Math.sin(turn), Math.cos(turn));
        targets.put(WalkerTuning.GROUND.get(i), new LegAngles(WalkerTuning.AMPLITUDE, azimuth));
      }
      last = targets;
      out.emit(TARGETS, new Targets(targets));
    }

    private double lag(Map<Leg, LegAngles> read) {
      double worst = 0;
      Map<Leg, LegAngles> wanted = last;
      if (wanted == null) {
        return 0;
      }
      for (Map.Entry<Leg, LegAngles> e : wanted.entrySet()) {
        LegAngles now = read.get(e.getKey());
        if (now != null) {
          worst = Math.max(worst, between(now, e.getValue()));
        }
      }
      return worst;
    }
  }

  /**
   * Reactor, the balance reflex: when the atom tips, it brings the ground legs back onto their
   * cones' axes, the widest and steadiest tripod.
   */
  record Balance(String name) implements Reactor {
    @Override
    public List<Port<?>> inputs() {
      return List.of(TIPPING);
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(TARGETS);
    }

    @Override
    public void react(Inputs in, Outputs out) {
      if (in.get(TIPPING) != null) {
        Map<Leg, LegAngles> targets = new EnumMap<>(Leg.class);
        for (Leg leg : WalkerTuning.GROUND) {
          targets.put(leg, LegAngles.AXIS);
        }
        out.emit(TARGETS, new Targets(targets));
      }
    }
  }

  /** Actuator: sends the targets to the legs. */
  record Drive(String name) implements Actuator {
    @Override
    public List<Port<?>> inputs() {
      return List.of(TARGETS);
    }

    @Override
    public void act(Inputs in, Body body) {
      Targets targets = in.get(TARGETS);
      if (targets != null) {
        targets.angles().forEach((leg, angles) -> body.command(Atom.target(leg), angles));
      }
    }
  }

  /** The angle between two directions of a leg in its cone, radians. */
  static double between(LegAngles a, LegAngles b) {
    double ax = Math.sin(a.elevation()) * Math.cos(a.azimuth());
    double ay = Math.sin(a.elevation()) * Math.sin(a.azimuth());
    double az = Math.cos(a.elevation());
    double bx = Math.sin(b.elevation()) * Math.cos(b.azimuth());
    double by = Math.sin(b.elevation()) * Math.sin(b.azimuth());
    double bz = Math.cos(b.elevation());
    return Math.acos(Math.max(-1, Math.min(1, ax * bx + ay * by + az * bz)));
  }
}

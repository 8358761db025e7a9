package org.armgals.examples.robots;

import java.util.Map;
import org.armgals.maam.Port;
import org.armgals.maam.Signal;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;

/** The signals flowing in the walker's cycle, and the ports that carry them. */
final class WalkerSignals {

  private WalkerSignals() {}

  /** Where the ground legs point now, as read. */
  record Joints(Map<Leg, LegAngles> angles) implements Signal {
    Joints {
      angles = Map.copyOf(angles);
    }
  }

  /** How many ground legs' tips touch the ground. */
  record Footing(int legsDown) implements Signal {}

  /** The atom leans more than it may, radians away from its resting attitude. */
  record Tipping(double lean) implements Signal {}

  /** Where the legs should go. */
  record Targets(Map<Leg, LegAngles> angles) implements Signal {
    Targets {
      angles = Map.copyOf(angles);
    }
  }

  /** Where the walker is on the ground, metres. */
  record Course(double x, double y) implements Signal {}

  static final Port<Joints> JOINTS = Port.of("joints", Joints.class);
  static final Port<Footing> FOOTING = Port.of("footing", Footing.class);
  static final Port<Tipping> TIPPING = Port.of("tipping", Tipping.class);
  static final Port<Targets> TARGETS = Port.of("targets", Targets.class);
  static final Port<Course> COURSE = Port.of("course", Course.class);
}

package org.armgals.examples.robots;

import java.util.List;
import org.armgals.maam.Port;
import org.armgals.maam.Signal;
import org.armgals.maam.spi.LegAngles;

/** The signals of the {@link EnergySaver} robot, and the ports that carry them. */
final class EnergySignals {

  private EnergySignals() {}

  /** The six legs' angles, as sensed at the start of the cycle, in the framework's leg order. */
  record LegPose(List<LegAngles> legs) implements Signal {
    LegPose {
      legs = List.copyOf(legs);
    }
  }

  /** Where every leg goes, in the framework's leg order, and the motors' torque limit (N·m). */
  record Stride(List<LegAngles> targets, double torqueLimit) implements Signal {
    Stride {
      targets = List.copyOf(targets);
    }
  }

  /**
   * An energy event: the battery's level this cycle.
   *
   * @param joules energy left
   * @param fraction of a full battery
   */
  record EnergyLevel(double joules, double fraction) implements Signal {}

  static final Port<LegPose> POSE = Port.of("pose", LegPose.class);
  static final Port<Stride> STRIDE = Port.of("stride", Stride.class);
  static final Port<EnergyLevel> LEVEL = Port.of("level", EnergyLevel.class);
}

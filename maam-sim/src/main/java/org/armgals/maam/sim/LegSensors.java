package org.armgals.maam.sim;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.Optional;
import java.util.OptionalInt;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;

/**
 * What one leg senses, read at the start of a control cycle.
 *
 * @param leg the leg
 * @param angles where the leg points in its cone: what the framework's body reads as {@link
 *     org.armgals.maam.spi.Atom#angles}; {@link LegAngles#AXIS} on a failed leg
 * @param torque1 torque the joint applies to the leg about its first axis (N·m)
 * @param torque2 torque the joint applies to the leg about its second axis (N·m)
 * @param tipContact whether the tip touched anything during the last control period
 * @param locked whether the connector is locked (ready to bind, or bound)
 * @param neighbour the id of the atom bound to this tip, if any
 * @param neighbourLeg the leg of that atom holding this tip, if any
 * @param proximity distance from the tip to the nearest thing along the leg's axis, or the ray's
 *     range if nothing is nearer (m)
 * @param failed whether the leg has failed (its motors are off; the other values read zero)
 */
public record LegSensors(
    Leg leg,
    LegAngles angles,
    double torque1,
    double torque2,
    boolean tipContact,
    boolean locked,
    OptionalInt neighbour,
    Optional<Leg> neighbourLeg,
    double proximity,
    boolean failed) {

  /** Checks that nothing is null. */
  public LegSensors {
    requireNonNull(leg, "leg");
    requireNonNull(angles, "angles");
    requireNonNull(neighbour, "neighbour");
    requireNonNull(neighbourLeg, "neighbourLeg");
  }

  /** How many numbers a leg's array in a trace's cycle line holds. */
  private static final int TRACED = 9;

  /**
   * What {@code leg} sensed, from its array in a trace's cycle line (docs/simulator.md gives the
   * layout): the trace keeps the joint's two angles, which this turns into {@link LegAngles} as the
   * running simulator does, bit for bit. The trace does not keep the neighbour's leg: it reads
   * empty.
   *
   * @throws IllegalArgumentException {@code values} is not such an array
   */
  public static LegSensors traced(Leg leg, List<? extends Number> values) {
    requireNonNull(leg, "leg");
    if (values.size() != TRACED) {
      throw new IllegalArgumentException(
          "leg "
              + leg
              + "'s trace array "
              + values
              + ": expected "
              + TRACED
              + " numbers (angle1, angle2, torque1, torque2, contact, locked, neighbour,"
              + " proximity, failed)");
    }
    int neighbour = (int) values.get(6).doubleValue();
    return new LegSensors(
        leg,
        JointAngles.legAngles(values.get(0).doubleValue(), values.get(1).doubleValue()),
        values.get(2).doubleValue(),
        values.get(3).doubleValue(),
        values.get(4).doubleValue() != 0,
        values.get(5).doubleValue() != 0,
        neighbour < 0 ? OptionalInt.empty() : OptionalInt.of(neighbour),
        Optional.empty(),
        values.get(7).doubleValue(),
        values.get(8).doubleValue() != 0);
  }
}

package org.armgals.maam.sim;

import java.util.Optional;
import java.util.OptionalInt;
import org.armgals.maam.spi.Leg;

/**
 * What one leg senses, read at the start of a control cycle.
 *
 * @param leg the leg
 * @param angle1 angle about the leg's first axis, from straight (rad)
 * @param angle2 angle about the leg's second axis, from straight (rad)
 * @param torque1 torque the joint applies to the leg about the first axis (N·m)
 * @param torque2 torque the joint applies to the leg about the second axis (N·m)
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
    double angle1,
    double angle2,
    double torque1,
    double torque2,
    boolean tipContact,
    boolean locked,
    OptionalInt neighbour,
    Optional<Leg> neighbourLeg,
    double proximity,
    boolean failed) {

  /** The angle between the leg and its rest axis (rad): what the cone limits. */
  public double coneAngle() {
    return Math.acos(Math.min(1, Math.cos(angle1) * Math.cos(angle2)));
  }
}

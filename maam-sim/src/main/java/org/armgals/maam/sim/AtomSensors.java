package org.armgals.maam.sim;

import java.util.List;
import org.armgals.maam.spi.Leg;

/**
 * What one atom senses, read at the start of a control cycle. A failed atom senses nothing: its
 * values read zero and its legs read failed.
 *
 * @param id the atom
 * @param timeNanos the virtual time of the reading (ns)
 * @param position where the kernel's centre is (m); ground truth, for traces and tests
 * @param orientation how the kernel is turned; ground truth, for traces and tests
 * @param tilt the angle between the kernel's up axis now and at the start (rad): what an
 *     inclinometer on the kernel reads
 * @param energy energy left in the battery (J)
 * @param failed whether the atom has failed
 * @param legs the six legs, in the order of {@link Leg#values()}
 */
public record AtomSensors(
    int id,
    long timeNanos,
    Vec3 position,
    Quat orientation,
    double tilt,
    double energy,
    boolean failed,
    List<LegSensors> legs) {

  /** Copies the leg list. */
  public AtomSensors {
    legs = List.copyOf(legs);
  }

  /** What {@code leg} senses. */
  public LegSensors leg(Leg leg) {
    return legs.get(leg.ordinal());
  }
}

package org.armgals.maam.sim;

import java.util.List;
import org.armgals.maam.spi.Leg;
import org.ode4j.math.DQuaternion;
import org.ode4j.math.DVector3;

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

  /**
   * Where {@code leg}'s tip is, as these readings place it (m): the leg pivots on the kernel's
   * surface along its rest axis, points as its {@link LegSensors#angles()} say (the simulator's
   * joint turned to those angles), then is turned by the kernel's {@link #orientation()}; {@code
   * params} gives the kernel's radius and the leg's length. It is where the simulator has the tip,
   * on either leg model (up to a jointed leg's give in its joint), and where the leg's proximity
   * ray starts: what a picture of the atom draws.
   */
  public Vec3 tip(Leg leg, AtomParams params) {
    double[] joint = JointAngles.of(leg(leg).angles());
    DQuaternion turn = Frames.legTurn(leg, joint[0], joint[1]);
    DVector3 d = Frames.rotate(turn, 0, 0, 1);
    double r = params.kernelRadius();
    double l = params.legLength();
    DVector3 local =
        Frames.rotate(
            Frames.of(orientation),
            leg.x() * r + d.get0() * l,
            leg.y() * r + d.get1() * l,
            leg.z() * r + d.get2() * l);
    return new Vec3(
        position.x() + local.get0(), position.y() + local.get1(), position.z() + local.get2());
  }
}

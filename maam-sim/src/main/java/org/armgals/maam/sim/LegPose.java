package org.armgals.maam.sim;

import org.armgals.maam.spi.Leg;
import org.ode4j.math.DQuaternion;
import org.ode4j.math.DVector3;

/**
 * A kinematic leg's pose in its kernel's frame at its two joint angles, worked out when its leg
 * asks ({@link KinematicLeg} asks only when it is needed: an atom at rest waves its legs without
 * anyone asking where they are). The joint turns the leg by {@code -a1} about axis 1 (fixed on the
 * kernel), then by {@code -a2} about axis 2 (fixed on the leg): the engine's universal joint's
 * convention, which the jointed model reads.
 */
final class LegPose {

  /** Per leg, by ordinal: its axes and rest pose, shared by every atom's (read, never written). */
  private static final double[][] AXIS1 = new double[Leg.values().length][];

  private static final double[][] AXIS2 = new double[Leg.values().length][];
  private static final DQuaternion[] REST = new DQuaternion[Leg.values().length];
  private static final double[][] REST_DIRECTION = new double[Leg.values().length][];

  static {
    for (Leg leg : Leg.values()) {
      AXIS1[leg.ordinal()] = Frames.axis1(leg);
      AXIS2[leg.ordinal()] = Frames.axis2(leg);
      REST[leg.ordinal()] = Frames.zOnto(leg);
      REST_DIRECTION[leg.ordinal()] = new double[] {leg.x(), leg.y(), leg.z()};
    }
  }

  /** Axis 1, fixed on the kernel (shared: not to be written). */
  final double[] axis1;

  private final double[] axis2;
  private final DQuaternion rest;
  private final double[] restDirection;
  private final double radius;
  private final double length;

  // Worked out in place: a moving leg is posed every step, and a pose that allocated would fill
  // the caches with garbage that pushes the atoms' own state out (decision 0079).
  private final DQuaternion local = new DQuaternion(1, 0, 0, 0);
  private final DVector3 direction = new DVector3(0, 0, 0);
  private final DVector3 turnedAxis2 = new DVector3();
  private final DQuaternion turn1 = new DQuaternion();
  private final DQuaternion turn2 = new DQuaternion();
  private final DVector3 tip = new DVector3();
  private final DVector3 centre = new DVector3();

  LegPose(Leg leg, double kernelRadius, double legLength) {
    this.axis1 = AXIS1[leg.ordinal()];
    this.axis2 = AXIS2[leg.ordinal()];
    this.rest = REST[leg.ordinal()];
    this.restDirection = REST_DIRECTION[leg.ordinal()];
    this.radius = kernelRadius;
    this.length = legLength;
  }

  /** Works out the pose at angles {@code (a1, a2)}. */
  void pose(double a1, double a2) {
    Frames.about(axis1, -a1, turn1);
    Frames.multiply(Frames.multiply(turn1, Frames.about(axis2, -a2, turn2), local), rest, local);
    Frames.rotate(local, 0, 0, 1, direction);
    Frames.rotate(turn1, axis2[0], axis2[1], axis2[2], turnedAxis2);
    double half = length / 2;
    centre.set(
        restDirection[0] * radius + direction.get0() * half,
        restDirection[1] * radius + direction.get1() * half,
        restDirection[2] * radius + direction.get2() * half);
    tip.set(
        restDirection[0] * radius + direction.get0() * length,
        restDirection[1] * radius + direction.get1() * length,
        restDirection[2] * radius + direction.get2() * length);
  }

  /** Works out axis 2 as axis 1's turn by angle {@code a1} turns it, and nothing else. */
  void turnAxis2(double a1) {
    Frames.rotate(Frames.about(axis1, -a1, turn1), axis2[0], axis2[1], axis2[2], turnedAxis2);
  }

  /** The leg's rotation (its local z is the leg's direction), until the next pose. */
  DQuaternion local() {
    return local;
  }

  /** The leg's unit direction. */
  DVector3 direction() {
    return direction;
  }

  /** The tip: the end of the far cap. */
  DVector3 tip() {
    return tip;
  }

  /** The capsule's centre. */
  DVector3 centre() {
    return centre;
  }

  /** Axis 2 as axis 1's turn has turned it. */
  DVector3 axis2() {
    return turnedAxis2;
  }

  /** The pivot, on the kernel's surface. */
  double pivot(int axis) {
    return restDirection[axis] * radius;
  }

  /**
   * Writes a box that holds the capsule (of radius {@code legRadius}) at any angles within a cone
   * of half-angle {@code halfAngle} into {@code to}: from the pivot out to the reach along the rest
   * direction, and as far as the tilted tip on the other two axes, a capsule's radius more all
   * round.
   */
  void coneBox(double halfAngle, double legRadius, double[] to) {
    double side = length * Math.sin(halfAngle) + legRadius;
    for (int axis = 0; axis < 3; axis++) {
      double d = restDirection[axis];
      if (d == 0) {
        to[2 * axis] = -side;
        to[2 * axis + 1] = side;
      } else {
        double near = d * (radius - legRadius);
        double far = d * (radius + length + legRadius);
        to[2 * axis] = Math.min(near, far);
        to[2 * axis + 1] = Math.max(near, far);
      }
    }
  }
}

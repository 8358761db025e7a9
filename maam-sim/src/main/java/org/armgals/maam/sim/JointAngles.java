package org.armgals.maam.sim;

import org.armgals.maam.spi.LegAngles;

/**
 * The one conversion between a leg joint's two axis angles, which the physics (ode4j's universal
 * joint, the servos, the cone's clamp and the trace) works in, and the framework's {@link
 * LegAngles}, which everything public speaks: a reading is converted as it leaves the physics, a
 * target as it enters it.
 */
final class JointAngles {

  private JointAngles() {}

  /**
   * The joint turned by {@code a1} then {@code a2} points the leg at {@code (sin a2, -sin a1 cos
   * a2, cos a1 cos a2)} in the frame (axis 1, axis 2, cone axis): its elevation is the angle to the
   * cone's axis, its azimuth the angle around it from axis 1.
   */
  static LegAngles legAngles(double a1, double a2) {
    double u = Math.sin(a2);
    double v = -Math.sin(a1) * Math.cos(a2);
    double w = Math.cos(a1) * Math.cos(a2);
    double elevation = Math.atan2(Math.hypot(u, v), w);
    double azimuth = elevation == 0 ? 0 : Math.atan2(v, u);
    return new LegAngles(elevation, azimuth);
  }

  /** The inverse of {@link #legAngles}: the joint's two angles {a1, a2} for {@code target}. */
  static double[] of(LegAngles target) {
    double e = target.elevation();
    double z = target.azimuth();
    double u = Math.sin(e) * Math.cos(z);
    double v = Math.sin(e) * Math.sin(z);
    double w = Math.cos(e);
    return new double[] {Math.atan2(-v, w), Math.asin(Math.max(-1, Math.min(1, u)))};
  }
}

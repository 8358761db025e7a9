package org.armgals.maam.sim;

import org.armgals.maam.spi.Leg;
import org.ode4j.math.DQuaternion;
import org.ode4j.math.DQuaternionC;
import org.ode4j.math.DVector3;

/** Quaternion arithmetic the engine's public API lacks. */
final class Frames {

  private Frames() {}

  static DQuaternion of(Quat q) {
    return new DQuaternion(q.w(), q.x(), q.y(), q.z());
  }

  /** {@code a · b}: rotate by {@code b}, then by {@code a}. */
  static DQuaternion multiply(DQuaternionC a, DQuaternionC b) {
    return multiply(a, b, new DQuaternion());
  }

  /** {@code a · b} written to {@code out} (which may be {@code a} or {@code b}), and returned. */
  static DQuaternion multiply(DQuaternionC a, DQuaternionC b, DQuaternion out) {
    double aw = a.get0();
    double ax = a.get1();
    double ay = a.get2();
    double az = a.get3();
    double bw = b.get0();
    double bx = b.get1();
    double by = b.get2();
    double bz = b.get3();
    return out.set(
        aw * bw - ax * bx - ay * by - az * bz,
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw);
  }

  /** The vector {@code (x, y, z)} rotated by {@code q}. */
  static DVector3 rotate(DQuaternionC q, double x, double y, double z) {
    return rotate(q, x, y, z, new DVector3());
  }

  /** The vector {@code (x, y, z)} rotated by {@code q}, written to {@code out} and returned. */
  static DVector3 rotate(DQuaternionC q, double x, double y, double z, DVector3 out) {
    double w = q.get0();
    double qx = q.get1();
    double qy = q.get2();
    double qz = q.get3();
    // t = 2 q_vec × v; v' = v + w t + q_vec × t
    double tx = 2 * (qy * z - qz * y);
    double ty = 2 * (qz * x - qx * z);
    double tz = 2 * (qx * y - qy * x);
    return out.set(
        x + w * tx + (qy * tz - qz * ty),
        y + w * ty + (qz * tx - qx * tz),
        z + w * tz + (qx * ty - qy * tx));
  }

  /** The rotation taking +z onto the unit axis {@code (x, y, z)} of a leg. */
  static DQuaternion zOnto(Leg leg) {
    double h = Math.sqrt(0.5);
    return switch (leg) {
      case PZ -> new DQuaternion(1, 0, 0, 0);
      case MZ -> new DQuaternion(0, 1, 0, 0);
      case PX -> new DQuaternion(h, 0, h, 0);
      case MX -> new DQuaternion(h, 0, -h, 0);
      case PY -> new DQuaternion(h, -h, 0, 0);
      case MY -> new DQuaternion(h, h, 0, 0);
    };
  }

  /**
   * A leg's rotation in its kernel's frame at angles {@code (a1, a2)}: the joint turns it by {@code
   * -a1} about axis 1 (fixed on the kernel), then by {@code -a2} about axis 2 (fixed on the leg),
   * from its rest pose along its axis: the engine's universal joint's convention, which the jointed
   * model reads.
   */
  static DQuaternion legTurn(Leg leg, double a1, double a2) {
    return multiply(multiply(about(axis1(leg), -a1), about(axis2(leg), -a2)), zOnto(leg));
  }

  /** The first tilt axis of {@code leg}, in the atom's frame. */
  static double[] axis1(Leg leg) {
    return switch (leg) {
      case PX, MX -> new double[] {0, 1, 0};
      case PY, MY -> new double[] {0, 0, 1};
      case PZ, MZ -> new double[] {1, 0, 0};
    };
  }

  /** The second tilt axis of {@code leg}, in the atom's frame. */
  static double[] axis2(Leg leg) {
    return switch (leg) {
      case PX, MX -> new double[] {0, 0, 1};
      case PY, MY -> new double[] {1, 0, 0};
      case PZ, MZ -> new double[] {0, 1, 0};
    };
  }

  /** The rotation by {@code angle} rad about the unit axis {@code a}. */
  static DQuaternion about(double[] a, double angle) {
    return about(a, angle, new DQuaternion());
  }

  /** The rotation by {@code angle} rad about the unit axis {@code a}, written to {@code out}. */
  static DQuaternion about(double[] a, double angle, DQuaternion out) {
    double s = Math.sin(angle / 2);
    return out.set(Math.cos(angle / 2), a[0] * s, a[1] * s, a[2] * s);
  }

  /** The inverse of the unit quaternion {@code q}. */
  static DQuaternion conjugate(DQuaternionC q) {
    return new DQuaternion(q.get0(), -q.get1(), -q.get2(), -q.get3());
  }
}

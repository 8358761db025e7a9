package org.armgals.maam.sim;

/** A rotation as a unit quaternion {@code w + xi + yj + zk}. */
public record Quat(double w, double x, double y, double z) {

  /** The rotation that changes nothing. */
  public static final Quat IDENTITY = new Quat(1, 0, 0, 0);

  /** Refuses quaternions that are not of unit length (to 1e-6). */
  public Quat {
    double n = w * w + x * x + y * y + z * z;
    if (!(Math.abs(n - 1) < 1e-6)) {
      throw new IllegalArgumentException(
          "quaternion (" + w + ", " + x + ", " + y + ", " + z + ") is not of unit length");
    }
  }

  /**
   * The rotation of {@code angle} radians about the axis {@code (ax, ay, az)}, which need not be of
   * unit length but must not be zero.
   */
  public static Quat ofAxisAngle(double ax, double ay, double az, double angle) {
    double n = Math.sqrt(ax * ax + ay * ay + az * az);
    if (!(n > 0) || !Double.isFinite(n)) {
      throw new IllegalArgumentException(
          "rotation axis (" + ax + ", " + ay + ", " + az + ") is not a finite non-zero vector");
    }
    double s = Math.sin(angle / 2) / n;
    return new Quat(Math.cos(angle / 2), ax * s, ay * s, az * s);
  }

  /**
   * The tripod pose: the atom's (1, 1, 1) diagonal points up, so the -x, -y and -z legs stand on
   * the ground like a tripod, the stable way for a lone atom to rest.
   */
  public static Quat tripod() {
    return ofAxisAngle(1, -1, 0, Math.acos(1 / Math.sqrt(3)));
  }
}

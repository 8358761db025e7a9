package org.armgals.maam.sim;

/**
 * The cone a leg moves in, over its two joint angles. A universal joint turned by {@code a1} and
 * {@code a2} tilts the leg by {@code t} with {@code cos t = cos a1 · cos a2}; the leg is in the
 * cone when {@code t <= halfAngle}.
 */
final class Cone {

  private final double halfAngle;
  private final double cosHalf;

  Cone(double halfAngle) {
    this.halfAngle = halfAngle;
    this.cosHalf = Math.cos(halfAngle);
  }

  /** The tilt of a leg turned by {@code (a1, a2)} (rad). */
  static double tilt(double a1, double a2) {
    return Math.acos(Math.min(1, Math.cos(a1) * Math.cos(a2)));
  }

  /**
   * The largest magnitude of one angle that keeps the leg in the cone when the other is {@code
   * other}: the stop of one axis, following the other.
   */
  double stopGiven(double other) {
    double c = Math.cos(other);
    if (c <= cosHalf) {
      return 0;
    }
    return Math.acos(Math.min(1, cosHalf / c));
  }

  private boolean inside(double a1, double a2) {
    return Math.cos(a1) * Math.cos(a2) >= cosHalf;
  }

  /** {@code a} within plus or minus the half-angle. */
  double limit(double a) {
    return Math.max(-halfAngle, Math.min(halfAngle, a));
  }

  /**
   * The factor that scales {@code (a1, a2)}, each {@link #limit limited}, down onto the cone's edge
   * if it is outside; 1 if it is inside.
   */
  double fit(double a1, double a2) {
    // tilt <= halfAngle exactly when cos a1 · cos a2 >= cos halfAngle (no acos on the way); and
    // cos a1 · cos a2 >= cos(|a1| + |a2|), so angles whose magnitudes sum to less than the
    // half-angle (a nanoradian less, for rounding) are inside without a cosine.
    if (Math.abs(a1) + Math.abs(a2) <= halfAngle - 1e-9 || inside(a1, a2)) {
      return 1;
    }
    double lo = 0;
    double hi = 1;
    for (int i = 0; i < 40; i++) {
      double mid = (lo + hi) / 2;
      if (inside(a1 * mid, a2 * mid)) {
        lo = mid;
      } else {
        hi = mid;
      }
    }
    return lo;
  }

  /**
   * {@code (a1, a2)} scaled down onto the cone's edge if it is outside, written to {@code out} (the
   * direction of the tilt is kept; {@code out} may be the input's array).
   */
  void clamp(double a1, double a2, double[] out) {
    a1 = limit(a1);
    a2 = limit(a2);
    double f = fit(a1, a2);
    out[0] = f == 1 ? a1 : a1 * f;
    out[1] = f == 1 ? a2 : a2 * f;
  }
}

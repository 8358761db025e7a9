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
   * if it is outside; 1 if it is inside: the last factor a 40-step bisection of [0, 1] finds
   * inside, bit for bit (decision 0079).
   */
  double fit(double a1, double a2) {
    return fit(a1, a2, true);
  }

  /** The bisection as it was before decision 0079, asking the cosines at every step: for tests. */
  double fitBySearch(double a1, double a2) {
    return fit(a1, a2, false);
  }

  /** {@link #fit}, the bisection {@code bounded} near the edge or not. */
  private double fit(double a1, double a2, boolean bounded) {
    // tilt <= halfAngle exactly when cos a1 · cos a2 >= cos halfAngle (no acos on the way); and
    // cos a1 · cos a2 >= cos(|a1| + |a2|), so angles whose magnitudes sum to less than the
    // half-angle (a nanoradian less, for rounding) are inside without a cosine.
    if (Math.abs(a1) + Math.abs(a2) <= halfAngle - 1e-9 || inside(a1, a2)) {
      return 1;
    }
    if (!bounded) {
      return bisect(a1, a2, Double.NaN, Double.NaN);
    }
    double f = edge(a1, a2);
    return bisect(a1, a2, surelyIn(a1, a2, f), surelyOut(a1, a2, f));
  }

  /**
   * {@link #MARGIN} below the edge {@code f} found for {@code (a1, a2)}, if the product of the
   * cosines there clears the cone's cosine by {@link #CLEARANCE}; NaN otherwise.
   */
  double surelyIn(double a1, double a2, double f) {
    double in = f - MARGIN;
    return f > 0 && f < 1 && Math.cos(a1 * in) * Math.cos(a2 * in) >= cosHalf + CLEARANCE
        ? in
        : Double.NaN;
  }

  /**
   * {@link #MARGIN} above the edge {@code f} found for {@code (a1, a2)}, if the product of the
   * cosines there falls short of the cone's cosine by {@link #CLEARANCE}; NaN otherwise.
   */
  double surelyOut(double a1, double a2, double f) {
    double out = f + MARGIN;
    return f > 0 && f < 1 && Math.cos(a1 * out) * Math.cos(a2 * out) <= cosHalf - CLEARANCE
        ? out
        : Double.NaN;
  }

  /**
   * The bisection, told that the factors below {@code sureIn} are inside and those above {@code
   * sureOut} outside, as {@link #inside} would find them: it asks the cosines only between the two,
   * the last steps or so. Without such a bound (NaN) it asks on that side at every step.
   */
  private double bisect(double a1, double a2, double sureIn, double sureOut) {
    double lo = 0;
    double hi = 1;
    for (int i = 0; i < 40; i++) {
      double mid = (lo + hi) / 2;
      boolean in = mid < sureIn || !(mid > sureOut) && inside(a1 * mid, a2 * mid);
      if (in) {
        lo = mid;
      } else {
        hi = mid;
      }
    }
    return lo;
  }

  /** How far either side of the edge found by Newton's method the bounds are put. */
  private static final double MARGIN = 4e-12;

  /**
   * By how much {@code cos(a1 f) · cos(a2 f)} must clear the cone's cosine at a bound for every
   * factor beyond it to fall on the same side: far more than twice the rounding of the product of
   * two cosines (each within an ulp, their arguments and the product rounded: under 1e-15 in all).
   */
  private static final double CLEARANCE = 1e-14;

  /**
   * For {@code (a1, a2)} outside the cone, the factor f at which {@code cos(a1 f) · cos(a2 f)}
   * meets the cone's cosine, by Newton's method (NaN if it is not found in (0, 1)); {@link #fit}
   * puts the bisection's bounds {@link #MARGIN} either side, and keeps each only where the product,
   * as {@link #inside} works it out, clears the cosine by {@link #CLEARANCE} on its side. Both
   * angles are within a right angle, so the product falls as f grows over [0, 1]: every factor
   * below a kept lower bound is then inside by more than rounding can undo, and every factor above
   * a kept upper bound outside. So the bounds never change what the bisection finds, however far
   * off the estimate is; a poor one only keeps fewer of them.
   */
  double edge(double a1, double a2) {
    if (!(Math.abs(a1) <= Math.PI / 2 && Math.abs(a2) <= Math.PI / 2)) {
      return Double.NaN;
    }
    // The tilt grows about in proportion to the factor: a first guess.
    double f = halfAngle / tilt(a1, a2);
    for (int i = 0; i < 8 && f > 0 && f < 1; i++) {
      double c1 = Math.cos(a1 * f);
      double c2 = Math.cos(a2 * f);
      double slope = -a1 * Math.sin(a1 * f) * c2 - a2 * c1 * Math.sin(a2 * f);
      double step = (c1 * c2 - cosHalf) / slope;
      f -= step;
      if (Math.abs(step) < 1e-15) {
        break;
      }
    }
    return f;
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

package org.armgals.maam.sim;

/** A point or a vector in world coordinates (m, or m/s², …, as its use says). */
public record Vec3(double x, double y, double z) {

  /** Refuses NaN and infinite components. */
  public Vec3 {
    if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z)) {
      throw new IllegalArgumentException(
          "vector (" + x + ", " + y + ", " + z + ") has a component that is not finite");
    }
  }
}

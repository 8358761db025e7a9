package org.armgals.maam.spi;

/**
 * Where a leg points inside its cone: {@code elevation} is the angle between the leg and the cone's
 * axis (0 on the axis), {@code azimuth} the angle around the axis. Radians; a read angle or a
 * target.
 *
 * @param elevation in [0, π)
 * @param azimuth in [-π, π]
 */
public record LegAngles(double elevation, double azimuth) {

  /** The leg on its cone's axis. */
  public static final LegAngles AXIS = new LegAngles(0, 0);

  /**
   * The leg tilted by {@code tilt} (rad) from its cone's axis towards {@code azimuth}, or, for a
   * negative tilt, by {@code -tilt} the opposite way: a leg swinging to and fro in one plane
   * through its cone's axis, its tilt signed.
   *
   * @throws IllegalArgumentException {@code azimuth} not in [-π, π], or {@code |tilt|} not in [0,
   *     π)
   */
  public static LegAngles swing(double tilt, double azimuth) {
    if (!(azimuth >= -Math.PI && azimuth <= Math.PI)) {
      throw new IllegalArgumentException("azimuth " + azimuth + ": expected in [-π, π]");
    }
    if (tilt < 0) {
      return new LegAngles(-tilt, azimuth > 0 ? azimuth - Math.PI : azimuth + Math.PI);
    }
    return new LegAngles(tilt, azimuth);
  }

  /** Checks the ranges. */
  public LegAngles {
    if (!(elevation >= 0 && elevation < Math.PI)) {
      throw new IllegalArgumentException("elevation " + elevation + ": expected in [0, π)");
    }
    if (!(azimuth >= -Math.PI && azimuth <= Math.PI)) {
      throw new IllegalArgumentException("azimuth " + azimuth + ": expected in [-π, π]");
    }
  }
}

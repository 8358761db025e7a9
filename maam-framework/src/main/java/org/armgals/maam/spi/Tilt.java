package org.armgals.maam.spi;

/**
 * The atom's attitude against gravity, in radians: 0, 0 when its z axis points up.
 *
 * @param roll rotation about x, in [-π, π]
 * @param pitch rotation about y, in [-π/2, π/2]
 */
public record Tilt(double roll, double pitch) {

  /** Upright. */
  public static final Tilt LEVEL = new Tilt(0, 0);

  /** Checks the ranges. */
  public Tilt {
    if (!(roll >= -Math.PI && roll <= Math.PI)) {
      throw new IllegalArgumentException("roll " + roll + ": expected in [-π, π]");
    }
    if (!(pitch >= -Math.PI / 2 && pitch <= Math.PI / 2)) {
      throw new IllegalArgumentException("pitch " + pitch + ": expected in [-π/2, π/2]");
    }
  }
}

package org.armgals.examples.plot;

import static java.util.Objects.requireNonNull;

import java.util.List;

/**
 * An atom as a picture shows it: its kernel's centre and radius and its legs' tips, in metres in
 * world coordinates (z up).
 *
 * @param id the atom's id, written beside it
 * @param centre the kernel's centre
 * @param radius the kernel's radius
 * @param legs the legs, each from the centre to its tip
 */
public record AtomView(String id, Vec centre, double radius, List<Leg> legs) {

  /** A point in the world, metres. */
  public record Vec(double x, double y, double z) {
    /** Refuses coordinates that cannot be drawn. */
    public Vec {
      if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z)) {
        throw new IllegalArgumentException(
            "a position must be finite, not (" + x + ", " + y + ", " + z + ")");
      }
    }
  }

  /**
   * A leg.
   *
   * @param tip where its tip is
   * @param bound whether its tip is bound to another atom's
   */
  public record Leg(Vec tip, boolean bound) {
    /** Checks the tip. */
    public Leg {
      requireNonNull(tip, "tip");
    }
  }

  /** Checks every component. */
  public AtomView {
    requireNonNull(id, "id");
    requireNonNull(centre, "centre");
    legs = List.copyOf(legs);
    if (!(radius > 0) || Double.isInfinite(radius)) {
      throw new IllegalArgumentException("an atom's radius must be positive, not " + radius);
    }
  }
}

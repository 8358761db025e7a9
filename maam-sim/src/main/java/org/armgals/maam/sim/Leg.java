package org.armgals.maam.sim;

/**
 * The six legs of an atom, named after the kernel axis they stand on. Each leg tilts about two axes
 * perpendicular to its own: {@code axis1} and {@code axis2} (for ±x: y then z; for ±y: z then x;
 * for ±z: x then y).
 */
public enum Leg {
  PX("+x", 1, 0, 0),
  NX("-x", -1, 0, 0),
  PY("+y", 0, 1, 0),
  NY("-y", 0, -1, 0),
  PZ("+z", 0, 0, 1),
  NZ("-z", 0, 0, -1);

  private final String label;
  private final double x;
  private final double y;
  private final double z;

  Leg(String label, double x, double y, double z) {
    this.label = label;
    this.x = x;
    this.y = y;
    this.z = z;
  }

  /** The label used in scene and trace files: {@code +x}, {@code -x}, … */
  public String label() {
    return label;
  }

  /** The leg on the opposite side of the kernel (the one a bound neighbour uses to face this). */
  public Leg opposite() {
    return values()[ordinal() ^ 1];
  }

  /** The x component of the leg's direction in the atom's frame. */
  public double x() {
    return x;
  }

  /** The y component of the leg's direction in the atom's frame. */
  public double y() {
    return y;
  }

  /** The z component of the leg's direction in the atom's frame. */
  public double z() {
    return z;
  }

  /** The leg whose label is {@code label}. */
  public static Leg ofLabel(String label) {
    for (Leg leg : values()) {
      if (leg.label.equals(label)) {
        return leg;
      }
    }
    throw new IllegalArgumentException(
        "leg label '" + label + "' is not one of +x, -x, +y, -y, +z, -z");
  }
}

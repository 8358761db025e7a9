package org.armgals.maam.spi;

/**
 * One of the six orthogonal legs of a MAAM atom, named after the axis of its cone in the atom's
 * frame: {@code PX} points along +x, {@code MX} along -x, and so on.
 */
public enum Leg {
  /** The leg along +x. */
  PX(1, 0, 0),
  /** The leg along -x. */
  MX(-1, 0, 0),
  /** The leg along +y. */
  PY(0, 1, 0),
  /** The leg along -y. */
  MY(0, -1, 0),
  /** The leg along +z. */
  PZ(0, 0, 1),
  /** The leg along -z. */
  MZ(0, 0, -1);

  private final int x;
  private final int y;
  private final int z;

  Leg(int x, int y, int z) {
    this.x = x;
    this.y = y;
    this.z = z;
  }

  /** The x component of the unit vector along the cone's axis. */
  public int x() {
    return x;
  }

  /** The y component of the unit vector along the cone's axis. */
  public int y() {
    return y;
  }

  /** The z component of the unit vector along the cone's axis. */
  public int z() {
    return z;
  }

  /** The leg pointing the other way. */
  public Leg opposite() {
    return values()[ordinal() ^ 1];
  }

  /** The leg's part of sensor and actuator names: {@code px}, {@code mx}, ... */
  public String key() {
    return name().toLowerCase(java.util.Locale.ROOT);
  }
}

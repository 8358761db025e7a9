package org.armgals.examples.plot;

import java.util.List;

/**
 * A box of the world with its faces along the axes, in metres: the frame a picture shows, the same
 * for every picture of a run, so that what moved shows where it went.
 *
 * @param minX least x
 * @param maxX greatest x, not below {@code minX}
 * @param minY least y
 * @param maxY greatest y, not below {@code minY}
 * @param minZ least z
 * @param maxZ greatest z, not below {@code minZ}
 */
public record Extent(double minX, double maxX, double minY, double maxY, double minZ, double maxZ) {

  /** Checks that every bound is finite and no maximum is below its minimum. */
  public Extent {
    double[] all = {minX, maxX, minY, maxY, minZ, maxZ};
    for (double v : all) {
      if (!Double.isFinite(v)) {
        throw new IllegalArgumentException("an extent's bounds must be finite, not " + v);
      }
    }
    if (maxX < minX || maxY < minY || maxZ < minZ) {
      throw new IllegalArgumentException(
          "an extent's maximum is below its minimum: x "
              + minX
              + " to "
              + maxX
              + ", y "
              + minY
              + " to "
              + maxY
              + ", z "
              + minZ
              + " to "
              + maxZ);
    }
  }

  /**
   * The least extent holding {@code atoms}: their kernels and their legs' tips.
   *
   * @throws IllegalArgumentException if there is no atom
   */
  public static Extent of(List<AtomView> atoms) {
    if (atoms.isEmpty()) {
      throw new IllegalArgumentException("the extent of no atom");
    }
    AtomView.Vec c = atoms.get(0).centre();
    Extent e = new Extent(c.x(), c.x(), c.y(), c.y(), c.z(), c.z());
    for (AtomView atom : atoms) {
      double r = atom.radius();
      c = atom.centre();
      e = e.including(c.x() - r, c.y() - r, c.z() - r).including(c.x() + r, c.y() + r, c.z() + r);
      for (AtomView.Leg leg : atom.legs()) {
        e = e.including(leg.tip().x(), leg.tip().y(), leg.tip().z());
      }
    }
    return e;
  }

  /** This extent grown to hold the point ({@code x}, {@code y}, {@code z}). */
  public Extent including(double x, double y, double z) {
    return new Extent(
        Math.min(minX, x),
        Math.max(maxX, x),
        Math.min(minY, y),
        Math.max(maxY, y),
        Math.min(minZ, z),
        Math.max(maxZ, z));
  }

  /** The least extent holding this one and {@code other}. */
  public Extent union(Extent other) {
    return including(other.minX, other.minY, other.minZ)
        .including(other.maxX, other.maxY, other.maxZ);
  }

  /** This extent grown by {@code margin} metres on every side. */
  Extent grown(double margin) {
    return new Extent(
        minX - margin, maxX + margin, minY - margin, maxY + margin, minZ - margin, maxZ + margin);
  }
}

package org.armgals.maam.sim;

import org.ode4j.ode.DAABBC;

/**
 * Axis-aligned bounding boxes as six numbers in an array, (min x, max x, min y, max y, min z, max
 * z) from an offset: the broad phase's, read without the engine's objects.
 */
final class Boxes {

  private Boxes() {}

  /** Copies the engine's box {@code b} into {@code to} at {@code at}. */
  static void copy(DAABBC b, double[] to, int at) {
    to[at] = b.getMin0();
    to[at + 1] = b.getMax0();
    to[at + 2] = b.getMin1();
    to[at + 3] = b.getMax1();
    to[at + 4] = b.getMin2();
    to[at + 5] = b.getMax2();
  }

  /** The engine's test: boxes that touch overlap. */
  static boolean overlap(double[] a, int i, double[] b, int j) {
    return a[i] <= b[j + 1]
        && b[j] <= a[i + 1]
        && a[i + 2] <= b[j + 3]
        && b[j + 2] <= a[i + 3]
        && a[i + 4] <= b[j + 5]
        && b[j + 4] <= a[i + 5];
  }

  /**
   * Whether the segment from {@code aim[from..from + 2]} along the unit direction {@code aim[from +
   * 3..from + 5]}, {@code length} long, surely misses the box in {@code box} at {@code at} (the box
   * taken a nanometre larger, for rounding).
   */
  static boolean segmentMisses(double[] box, int at, double[] aim, int from, double length) {
    double enter = 0;
    double leave = length;
    for (int axis = 0; axis < 3; axis++) {
      double start = aim[from + axis];
      double along = aim[from + 3 + axis];
      double lo = box[at + 2 * axis] - 1e-9;
      double hi = box[at + 2 * axis + 1] + 1e-9;
      if (along == 0) {
        if (start < lo || start > hi) {
          return true;
        }
      } else {
        double a = (lo - start) / along;
        double b = (hi - start) / along;
        enter = Math.max(enter, Math.min(a, b));
        leave = Math.min(leave, Math.max(a, b));
        if (enter > leave) {
          return true;
        }
      }
    }
    return false;
  }
}

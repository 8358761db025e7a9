package org.armgals.maam.sim;

import java.util.Arrays;

/**
 * The broad phase over atoms: a grid of square cells in the ground's plane (x, y), each as wide as
 * the widest atom's bounding box, rebuilt every step. An atom is filed under the cell of its box's
 * lowest corner, so the atoms whose boxes overlap a box lie in that box's cells and one cell before
 * them on each axis: finding an atom's neighbours costs the same whatever the number of atoms,
 * where the engine's hash space allocates and clears a bit per pair of its entries on every call
 * (decision 0062).
 *
 * <p>Atoms are visited in the order of their index, and each cell's atoms in the reverse order of
 * theirs, so the pairs come out in the same order every run.
 */
final class AtomGrid {

  /** A pair of atoms whose boxes overlap, {@code a < b} (indexes in the list given to rebuild). */
  interface PairVisitor {
    void visit(int a, int b);
  }

  /** An atom whose box overlaps the box asked about. */
  interface AtomVisitor {
    void visit(int atom);
  }

  private int count;
  private double cell = 1;
  private double[] box = new double[0];
  private int[] cellX = new int[0];
  private int[] cellY = new int[0];
  private int[] next = new int[0];
  private int[] heads = new int[0];
  private int mask;

  /**
   * Files {@code count} atoms' bounding boxes, atom i's in {@code boxes[6i..6i+5]} as (min x, max
   * x, min y, max y, min z, max z): call before the queries of a step. The array is read, not
   * copied, until the next rebuild.
   */
  void rebuild(double[] boxes, int count) {
    this.count = count;
    this.box = boxes;
    if (cellX.length < count) {
      cellX = new int[count];
      cellY = new int[count];
      next = new int[count];
      int size = Integer.highestOneBit(Math.max(1, 2 * count - 1)) << 1;
      heads = new int[size];
      mask = size - 1;
    }
    fitCells(boxes, count);
    Arrays.fill(heads, -1);
    for (int i = 0; i < count; i++) {
      int x = cellOf(box[6 * i]);
      int y = cellOf(box[6 * i + 2]);
      cellX[i] = x;
      cellY[i] = y;
      int h = hash(x, y);
      next[i] = heads[h];
      heads[h] = i;
    }
  }

  /**
   * Sizes the cells for {@code count} boxes as {@link #rebuild} does, filing none: as wide as the
   * widest box, so that a box spans at most two cells on an axis. A degenerate or broken box (NaN)
   * leaves the cells as they were.
   */
  void fitCells(double[] boxes, int count) {
    double widest = widest(boxes, count);
    if (widest > 0 && widest < Double.POSITIVE_INFINITY) {
      cell = widest;
    }
  }

  /**
   * The widest of {@code count} boxes (box i at 6i in {@code boxes}) on the ground's plane: its
   * width along x or y, whichever is greater. NaN if a box is broken.
   */
  static double widest(double[] boxes, int count) {
    double widest = 0;
    for (int o = 0; o < 6 * count; o += 6) {
      widest = Math.max(widest, Math.max(boxes[o + 1] - boxes[o], boxes[o + 3] - boxes[o + 2]));
    }
    return widest;
  }

  /**
   * Where {@link #forEachPairOf forEachPairOf(a, ...)} visits the cell of the box at {@code b} in
   * {@code boxes}, for the box at {@code a} (offsets into {@code boxes}), with the cells as last
   * {@link #fitCells fitted}: the cells it visits are numbered 0 to 8 in its order, and -1 is one
   * it does not visit. Within a cell it visits atoms from the last to the first.
   */
  int visitOrder(double[] boxes, int a, int b) {
    int dx = cellOf(boxes[b]) - cellOf(boxes[a]);
    int dy = cellOf(boxes[b + 2]) - cellOf(boxes[a + 2]);
    if (dx < -1 || dx > 1 || dy < -1 || dy > 1) {
      return -1;
    }
    return 3 * (dy + 1) + dx + 1;
  }

  /** Visits every pair of atoms whose boxes overlap, each once. */
  void forEachPair(PairVisitor visitor) {
    for (int a = 0; a < count; a++) {
      forEachPairOf(a, visitor);
    }
  }

  /** Visits every pair of atom {@code a} and a later atom whose boxes overlap. */
  void forEachPairOf(int a, PairVisitor visitor) {
    int x = cellX[a];
    int y = cellY[a];
    for (int dy = -1; dy <= 1; dy++) {
      for (int dx = -1; dx <= 1; dx++) {
        for (int b = heads[hash(x + dx, y + dy)]; b >= 0; b = next[b]) {
          if (b > a && cellX[b] == x + dx && cellY[b] == y + dy && overlap(a, b)) {
            visitor.visit(a, b);
          }
        }
      }
    }
  }

  /** Visits every atom whose box overlaps {@code query}, a box as in {@link #rebuild}. */
  void forEachOverlapping(double[] query, AtomVisitor visitor) {
    double minX = query[0];
    double maxX = query[1];
    double minY = query[2];
    double maxY = query[3];
    long x0 = cellOf(minX) - 1L;
    long x1 = cellOf(maxX);
    long y0 = cellOf(minY) - 1L;
    long y1 = cellOf(maxY);
    if ((x1 - x0 + 1) * (y1 - y0 + 1) > count) {
      // A box over more cells than there are atoms: looking at every atom is cheaper.
      for (int a = 0; a < count; a++) {
        if (overlaps(a, query)) {
          visitor.visit(a);
        }
      }
      return;
    }
    for (long y = y0; y <= y1; y++) {
      for (long x = x0; x <= x1; x++) {
        for (int a = heads[hash((int) x, (int) y)]; a >= 0; a = next[a]) {
          if (cellX[a] == x && cellY[a] == y && overlaps(a, query)) {
            visitor.visit(a);
          }
        }
      }
    }
  }

  private int cellOf(double v) {
    double c = Math.floor(v / cell);
    // Far out or broken positions share the outermost cells: still correct, only slower.
    return (int) Math.max(-1e9, Math.min(1e9, c));
  }

  private int hash(int x, int y) {
    int h = x * 0x9E3779B1 + y * 0x85EBCA77;
    return (h ^ (h >>> 15)) & mask;
  }

  private boolean overlap(int a, int b) {
    return Boxes.overlap(box, 6 * a, box, 6 * b);
  }

  private boolean overlaps(int a, double[] q) {
    return Boxes.overlap(box, 6 * a, q, 0);
  }
}

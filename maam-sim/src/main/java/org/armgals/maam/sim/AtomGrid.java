package org.armgals.maam.sim;

import java.util.Arrays;
import java.util.List;
import org.ode4j.ode.DAABBC;
import org.ode4j.ode.DGeom;

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
   * Files the atoms' bounding boxes, {@code geoms.get(i)}'s for atom i, brought up to date: call
   * before the queries of a step.
   */
  void rebuild(List<? extends DGeom> geoms) {
    count = geoms.size();
    if (box.length < 6 * count) {
      box = new double[6 * count];
      cellX = new int[count];
      cellY = new int[count];
      next = new int[count];
      int size = Integer.highestOneBit(Math.max(1, 2 * count - 1)) << 1;
      heads = new int[size];
      mask = size - 1;
    }
    double widest = 0;
    for (int i = 0; i < count; i++) {
      DAABBC b = geoms.get(i).getAABB();
      int o = 6 * i;
      box[o] = b.getMin0();
      box[o + 1] = b.getMax0();
      box[o + 2] = b.getMin1();
      box[o + 3] = b.getMax1();
      box[o + 4] = b.getMin2();
      box[o + 5] = b.getMax2();
      widest = Math.max(widest, Math.max(box[o + 1] - box[o], box[o + 3] - box[o + 2]));
    }
    // A box as wide as a cell spans at most two cells on an axis; a degenerate or broken box
    // (NaN) leaves the cell as it was.
    if (widest > 0 && widest < Double.POSITIVE_INFINITY) {
      cell = widest;
    }
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

  /** Visits every pair of atoms whose boxes overlap, each once. */
  void forEachPair(PairVisitor visitor) {
    for (int a = 0; a < count; a++) {
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
  }

  /** Visits every atom whose box overlaps {@code query}. */
  void forEachOverlapping(DAABBC query, AtomVisitor visitor) {
    double minX = query.getMin0();
    double maxX = query.getMax0();
    double minY = query.getMin1();
    double maxY = query.getMax1();
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
    int i = 6 * a;
    int j = 6 * b;
    return box[i] <= box[j + 1]
        && box[j] <= box[i + 1]
        && box[i + 2] <= box[j + 3]
        && box[j + 2] <= box[i + 3]
        && box[i + 4] <= box[j + 5]
        && box[j + 4] <= box[i + 5];
  }

  private boolean overlaps(int a, DAABBC q) {
    int i = 6 * a;
    return box[i] <= q.getMax0()
        && q.getMin0() <= box[i + 1]
        && box[i + 2] <= q.getMax1()
        && q.getMin1() <= box[i + 3]
        && box[i + 4] <= q.getMax2()
        && q.getMin2() <= box[i + 5];
  }
}

package org.armgals.maam.sim;

import java.util.Arrays;

/**
 * The pairs of atoms whose boxes overlap, each atom's in the order {@link AtomGrid#forEachPairOf}
 * gives them, without searching the grid every step (decision 0076). Each atom keeps a list of the
 * atoms after it whose boxes, grown by a margin, overlapped its own when the lists were made. The
 * lists hold while no box has left its own grown by half the margin: then two boxes that overlap
 * now overlapped, grown, by half the margin or more, far more than rounding. A step looks only at
 * the lists, and the lists are made again, with a grid of the grown boxes, once a box has left.
 *
 * <p>A step's pairs of an atom are those of its list whose boxes overlap and whose cells in the
 * collisions' grid neighbour its own, in the order that grid visits them: the very pairs, in the
 * very order, that filing every box in the grid and searching it gives, and so the same contacts in
 * the same order.
 */
final class NearPairs {

  /** The margin boxes are grown by, as a share of the widest box's width on the ground's plane. */
  private static final double MARGIN = 0.1;

  private final AtomGrid grown = new AtomGrid();

  /** The atoms' boxes when the lists were made, grown by the margin, atom i's at 6i. */
  private double[] made = new double[0];

  /** Half the margin: how far a box may go past its box when the lists were made. */
  private double slack;

  /** The number of atoms the lists are for, -1 before they are first made. */
  private int count = -1;

  /** Atom a's list is {@code later[first[a]]} to {@code later[first[a + 1] - 1]}. */
  private int[] first = new int[1];

  private int[] later = new int[16];
  private int listed;
  private final AtomGrid.PairVisitor list = this::list;

  /** A step's pairs of one atom: the grid's order of the cell, then the other atom's index. */
  private long[] found = new long[8];

  /**
   * Readies the lists for {@code count} atoms' boxes (atom i's at 6i in {@code boxes}), making them
   * again if a box has left the room its list leaves it; false if a box is not finite, for which
   * the lists hold nothing (then search the grid).
   */
  boolean update(double[] boxes, int count) {
    if (count == this.count && inside(boxes, count)) {
      return true;
    }
    this.count = -1;
    for (int o = 0; o < 6 * count; o++) {
      if (!Double.isFinite(boxes[o])) {
        return false;
      }
    }
    make(boxes, count, Math.max(MARGIN * AtomGrid.widest(boxes, count), 1e-6));
    return true;
  }

  /** Whether every box is in its room: its box when the lists were made, and the slack. */
  private boolean inside(double[] boxes, int count) {
    for (int o = 0; o < 6 * count; o += 2) {
      if (!(boxes[o] >= made[o] + slack && boxes[o + 1] <= made[o + 1] - slack)) {
        return false;
      }
    }
    return true;
  }

  private void make(double[] boxes, int count, double margin) {
    if (made.length < 6 * count) {
      made = new double[6 * count];
      first = new int[count + 1];
    }
    for (int o = 0; o < 6 * count; o += 2) {
      made[o] = boxes[o] - margin;
      made[o + 1] = boxes[o + 1] + margin;
    }
    slack = margin / 2;
    grown.rebuild(made, count);
    listed = 0;
    for (int a = 0; a < count; a++) {
      first[a] = listed;
      grown.forEachPairOf(a, list);
    }
    first[count] = listed;
    this.count = count;
  }

  private void list(int a, int b) {
    if (listed == later.length) {
      later = Arrays.copyOf(later, 2 * listed);
    }
    later[listed++] = b;
  }

  /**
   * Visits the pairs of atom {@code a} and a later atom whose boxes overlap, as {@link
   * AtomGrid#forEachPairOf} on {@code grid} would with {@code boxes} filed: {@code grid}'s cells
   * are {@link AtomGrid#fitCells fitted} to {@code boxes}, and the lists {@link #update updated}.
   */
  void forEachPairOf(int a, double[] boxes, AtomGrid grid, AtomGrid.PairVisitor visitor) {
    int n = 0;
    for (int k = first[a]; k < first[a + 1]; k++) {
      int b = later[k];
      if (!Boxes.overlap(boxes, 6 * a, boxes, 6 * b)) {
        continue;
      }
      int cell = grid.visitOrder(boxes, 6 * a, 6 * b);
      if (cell < 0) {
        continue;
      }
      if (n == found.length) {
        found = Arrays.copyOf(found, 2 * n);
      }
      // The grid visits its cells in order, and a cell's atoms from the last.
      long key = (long) cell << 32 | (Integer.MAX_VALUE - b);
      int at = n++;
      while (at > 0 && found[at - 1] > key) {
        found[at] = found[at - 1];
        at--;
      }
      found[at] = key;
    }
    for (int i = 0; i < n; i++) {
      visitor.visit(a, Integer.MAX_VALUE - (int) found[i]);
    }
  }
}

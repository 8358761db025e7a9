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
   * The filed atoms by rows of cells, for {@link #forEachOverlapping}: over the rectangle of cells
   * the atoms lie in ({@link #rowsX0}, {@link #rowsY0}, {@link #rowsWidth} cells wide), the atoms
   * of cell k (row-major) at {@code rowAtoms[rowStart[k] .. rowStart[k + 1])}, so that a query
   * reads each row of cells it spans as one run (decision 0079). Filed by {@link #fileRows} after a
   * {@link #rebuild}, and only if the rectangle has few cells for the atoms; {@link #byRows} says
   * whether they are filed so now.
   */
  private boolean byRows;

  private int rowsX0;
  private int rowsY0;
  private int rowsWidth;
  private int rowsHeight;
  private int[] rowStart = new int[0];
  private int[] rowAtoms = new int[0];

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
    byRows = false;
  }

  /**
   * After a {@link #rebuild}, files the atoms by rows of cells (see {@link #rowStart}) for the
   * queries until the next, by a counting sort, unless their cells span more than four per atom
   * (atoms far apart: the queries then use the hash of cells, as they do without this call). Called
   * before the queries, never during them: lanes query at once, and a query only reads.
   */
  void fileRows() {
    byRows = false;
    if (count == 0) {
      return;
    }
    int minX = cellX[0];
    int maxX = minX;
    int minY = cellY[0];
    int maxY = minY;
    for (int i = 1; i < count; i++) {
      minX = Math.min(minX, cellX[i]);
      maxX = Math.max(maxX, cellX[i]);
      minY = Math.min(minY, cellY[i]);
      maxY = Math.max(maxY, cellY[i]);
    }
    long width = (long) maxX - minX + 1;
    long height = (long) maxY - minY + 1;
    if (width * height > 4L * count + 64) {
      return;
    }
    int cells = (int) (width * height);
    if (rowStart.length < cells + 1) {
      rowStart = new int[Math.max(cells + 1, 2 * rowStart.length)];
    }
    if (rowAtoms.length < count) {
      rowAtoms = new int[Math.max(count, 2 * rowAtoms.length)];
    }
    rowsX0 = minX;
    rowsY0 = minY;
    rowsWidth = (int) width;
    rowsHeight = (int) height;
    Arrays.fill(rowStart, 0, cells + 1, 0);
    for (int i = 0; i < count; i++) {
      rowStart[rowCell(i) + 1]++;
    }
    for (int k = 0; k < cells; k++) {
      rowStart[k + 1] += rowStart[k];
    }
    for (int i = 0; i < count; i++) {
      // rowStart[k] runs ahead while cell k is filled, and ends where cell k + 1 starts.
      rowAtoms[rowStart[rowCell(i)]++] = i;
    }
    for (int k = cells; k > 0; k--) {
      rowStart[k] = rowStart[k - 1];
    }
    rowStart[0] = 0;
    byRows = true;
  }

  /**
   * Whether queries read the atoms by rows of cells until the next rebuild, not through the hash:
   * for tests.
   */
  boolean queriedByRows() {
    return byRows;
  }

  private int rowCell(int i) {
    return (cellY[i] - rowsY0) * rowsWidth + cellX[i] - rowsX0;
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

  /**
   * Visits every atom whose box overlaps {@code query}, a box as in {@link #rebuild}, each once, in
   * no order to be relied on.
   */
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
    if (byRows) {
      forEachInRows(query, x0, x1, y0, y1, visitor);
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

  /**
   * The atoms of cells {@code x0..x1} by {@code y0..y1} (clipped to the filed rectangle) whose
   * boxes overlap {@code query}: a run of {@link #rowAtoms} per row.
   */
  private void forEachInRows(
      double[] query, long x0, long x1, long y0, long y1, AtomVisitor visitor) {
    long fromX = Math.max(x0, rowsX0);
    long toX = Math.min(x1, rowsX0 + rowsWidth - 1L);
    long fromY = Math.max(y0, rowsY0);
    long toY = Math.min(y1, rowsY0 + rowsHeight - 1L);
    for (long y = fromY; y <= toY && fromX <= toX; y++) {
      int row = (int) (y - rowsY0) * rowsWidth - rowsX0;
      int end = rowStart[row + (int) toX + 1];
      for (int k = rowStart[row + (int) fromX]; k < end; k++) {
        int a = rowAtoms[k];
        if (overlaps(a, query)) {
          visitor.visit(a);
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

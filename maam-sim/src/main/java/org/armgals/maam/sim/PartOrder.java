package org.armgals.maam.sim;

/**
 * The order in which the engine's simple space keeps its geometries, followed without the space: a
 * geometry added goes to the front of the list; one that moves while clean goes to the front and is
 * dirty until the space is cleaned. Parts are numbered from 0, in the order they were added.
 */
final class PartOrder {

  /** When each part last went to the front. */
  private final long[] fronted;

  private final int[] order;
  private long clock;
  private boolean sorted;

  /** A bit per part: moved since the last {@link #clean()}. */
  private int dirty;

  /**
   * {@code count} parts (at most 31), added in number order and all dirty, as new geometries are.
   */
  PartOrder(int count) {
    if (count < 1 || count > 31) {
      throw new IllegalArgumentException(count + " parts: expected 1 to 31");
    }
    fronted = new long[count];
    order = new int[count];
    for (int p = 0; p < count; p++) {
      fronted[p] = ++clock;
    }
    dirty = (1 << count) - 1;
  }

  int count() {
    return order.length;
  }

  /** Part {@code part} moved. */
  void moved(int part) {
    int bit = 1 << part;
    if ((dirty & bit) == 0) {
      dirty |= bit;
      fronted[part] = ++clock;
      sorted = false;
    }
  }

  /** The space was cleaned. */
  void clean() {
    dirty = 0;
  }

  /** The part at position {@code i} of the list, the front at 0. */
  int get(int i) {
    if (!sorted) {
      sort();
    }
    return order[i];
  }

  private void sort() {
    // Insertion sort, latest to the front: a handful of parts, mostly in order already.
    for (int i = 0; i < order.length; i++) {
      int p = i;
      int j = i;
      while (j > 0 && fronted[order[j - 1]] < fronted[p]) {
        order[j] = order[j - 1];
        j--;
      }
      order[j] = p;
    }
    sorted = true;
  }
}

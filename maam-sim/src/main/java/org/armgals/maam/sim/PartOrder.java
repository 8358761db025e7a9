package org.armgals.maam.sim;

/**
 * The order in which the engine's simple space keeps its geometries, followed without the space: a
 * geometry added goes to the front of the list; one that moves while clean goes to the front and is
 * dirty until the space is cleaned. Parts are numbered from 0, in the order they were added.
 */
final class PartOrder {

  /** The part at each position, front first, four bits each. */
  private long order;

  private final int count;

  /** A bit per part: moved since the last {@link #clean()}. */
  private int dirty;

  /**
   * {@code count} parts (at most 16), added in number order and all dirty, as new geometries are.
   */
  PartOrder(int count) {
    if (count < 1 || count > 16) {
      throw new IllegalArgumentException(count + " parts: expected 1 to 16");
    }
    this.count = count;
    for (int p = 0; p < count; p++) {
      // Each goes in front of those before it.
      order = order << 4 | p;
    }
    dirty = (1 << count) - 1;
  }

  int count() {
    return count;
  }

  /** Part {@code part} moved. */
  void moved(int part) {
    int bit = 1 << part;
    if ((dirty & bit) != 0) {
      return;
    }
    dirty |= bit;
    int at = 0;
    while (get(at) != part) {
      at++;
    }
    long before = order & ((1L << 4 * at) - 1);
    long after = at == 15 ? 0 : order & -(1L << 4 * (at + 1));
    order = after | before << 4 | part;
  }

  /** The space was cleaned. */
  void clean() {
    dirty = 0;
  }

  /** The part at position {@code i} of the list, the front at 0. */
  int get(int i) {
    return (int) (order >>> 4 * i) & 15;
  }
}

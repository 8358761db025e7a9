package org.armgals.bench.gals;

/**
 * The work of one reactive entity in one cycle, the same for armgals and the raw loop: 50 small
 * computations, standing in for a MAAM robot's 50 behavior modules.
 */
final class Work {
  /** Computations per entity per cycle. */
  static final int MODULES = 50;

  private Work() {}

  /** Runs the 50 computations on {@code seed} and answers the result (kept, so none is elided). */
  static long cycle(long seed) {
    long x = seed;
    for (int m = 0; m < MODULES; m++) {
      x ^= x << 13;
      x ^= x >>> 7;
      x ^= x << 17;
      x += m;
    }
    return x;
  }
}

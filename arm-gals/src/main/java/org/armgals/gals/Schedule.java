package org.armgals.gals;

/**
 * The release schedule of a real-time island under its {@link OverrunPolicy}: given when a release
 * was due and when its cycle ended, when the next one is due. Pure arithmetic, no time read.
 */
final class Schedule {
  private final long period;
  private final OverrunPolicy policy;
  private long skipped;

  Schedule(long period, OverrunPolicy policy) {
    this.period = period;
    this.policy = policy;
  }

  /**
   * When the release after the one due at {@code due}, whose cycle ended at {@code end}, is due.
   */
  long next(long due, long end) {
    long next = due + period;
    if (end <= next) {
      return next;
    }
    return switch (policy) {
      case CATCH_UP -> next;
      case REPORT_ONLY -> end;
      case SKIP -> {
        long missed = (end - next + period - 1) / period;
        skipped += missed;
        yield next + missed * period;
      }
    };
  }

  /** How many releases {@link OverrunPolicy#SKIP} dropped so far, then zero. */
  long takeSkipped() {
    long s = skipped;
    skipped = 0;
    return s;
  }
}

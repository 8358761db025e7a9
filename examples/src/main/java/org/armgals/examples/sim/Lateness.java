package org.armgals.examples.sim;

import java.util.Locale;
import java.util.Optional;
import org.armgals.examples.run.Summary;

/**
 * How a run paced to real time fell behind its schedule: the cycles it missed (those that ended
 * more than a period after their time), in how many spells (runs of missed cycles), and the
 * furthest it fell behind. A spell of many missed cycles after one long stall (a collection, the
 * machine busy elsewhere) reads differently from cycles that are each too slow, and the summary
 * says which it was.
 */
final class Lateness {
  private final long periodNanos;
  private long missed;
  private long spells;
  private boolean late;
  private long worstNanos;
  private long worstCycle = -1;

  Lateness(long periodNanos) {
    this.periodNanos = periodNanos;
  }

  /**
   * Cycle {@code cycle} ended {@code behindNanos} after its time on the schedule (negative: ahead
   * of it); it is missed if that is more than a period.
   */
  void ended(long cycle, long behindNanos) {
    boolean missedThis = behindNanos > periodNanos;
    if (missedThis) {
      missed++;
      if (!late) {
        spells++;
      }
      if (behindNanos > worstNanos) {
        worstNanos = behindNanos;
        worstCycle = cycle;
      }
    }
    late = missedThis;
  }

  long missed() {
    return missed;
  }

  /** The summary's line, if any cycle was missed. */
  Optional<Summary.Entry> entry() {
    if (missed == 0) {
      return Optional.empty();
    }
    return Optional.of(
        new Summary.Entry(
            "late spells",
            String.format(
                Locale.ROOT,
                "%d (runs of missed cycles); the furthest behind %.1f ms, at cycle %d (%.2f s)",
                spells,
                worstNanos / 1e6,
                worstCycle,
                worstCycle * periodNanos / 1e9)));
  }
}

package org.armgals.active.spi;

import java.time.Duration;
import java.util.Objects;
import org.HdrHistogram.Histogram;

/**
 * The figures of something released in cycles with a period: a clock's instants or an island's
 * cycles. One recorder for both, so that a clock and an island count an overrun, a jitter and a
 * mean period the same way.
 *
 * <p>Written by the thread that runs the cycles, read by anyone: every method is synchronized (one
 * uncontended lock per cycle).
 *
 * <p>A cycle overruns when its release's lateness plus its length exceeds the period, that is when
 * it ends after the next release was due. An overrun that would not have been one without the time
 * spent applying adaptation requests is also an adaptation overrun.
 */
public final class CycleRecorder {

  /**
   * What a recorder has seen.
   *
   * @param instants cycles recorded
   * @param overruns cycles that ended after the next release was due
   * @param skipped releases skipped (a cycle that overran makes the releases it covered skipped)
   * @param meanPeriod the mean time between releases (zero before the second)
   * @param jitterP50 the median lateness of a release behind its schedule
   * @param jitterP99 its 99th percentile
   * @param jitterMax its maximum
   * @param cycleMax the longest cycle, from its release to its end
   * @param adaptations adaptation requests applied
   * @param adaptationMax the longest time a cycle spent applying them
   * @param adaptationOverruns overruns that the adaptations alone caused
   * @param failures cycles that failed
   */
  public record Figures(
      long instants,
      long overruns,
      long skipped,
      Duration meanPeriod,
      Duration jitterP50,
      Duration jitterP99,
      Duration jitterMax,
      Duration cycleMax,
      long adaptations,
      Duration adaptationMax,
      long adaptationOverruns,
      long failures) {}

  private final long period;
  private final Histogram jitter = new Histogram(Duration.ofSeconds(10).toNanos(), 3);
  private long instants;
  private long overruns;
  private long skipped;
  private long firstRelease;
  private long lastRelease;
  private long cycleMax;
  private long adaptations;
  private long adaptationMax;
  private long adaptationOverruns;
  private long failures;

  /**
   * A recorder of cycles released every {@code period}.
   *
   * @throws IllegalArgumentException if {@code period} is not positive
   */
  public CycleRecorder(Duration period) {
    Objects.requireNonNull(period, "period");
    if (period.isNegative() || period.isZero()) {
      throw new IllegalArgumentException("period must be > 0, was " + period);
    }
    this.period = period.toNanos();
  }

  /**
   * Records one cycle with no adaptation.
   *
   * @param releasedAt when it was released, in nanoseconds of any origin
   * @param lateness how late the release was behind its schedule, in nanoseconds
   * @param cycle from the release to the end of the cycle, in nanoseconds
   * @return whether the cycle overran
   */
  public synchronized boolean record(long releasedAt, long lateness, long cycle) {
    return record(releasedAt, lateness, cycle, 0, 0);
  }

  /**
   * Records one cycle.
   *
   * @param releasedAt when it was released, in nanoseconds of any origin
   * @param lateness how late the release was behind its schedule, in nanoseconds
   * @param cycle from the release to the end of the cycle, in nanoseconds
   * @param adaptation the part of {@code cycle} spent applying adaptation requests
   * @param applied how many requests were applied
   * @return whether the cycle overran
   */
  public synchronized boolean record(
      long releasedAt, long lateness, long cycle, long adaptation, int applied) {
    if (instants == 0) {
      firstRelease = releasedAt;
    }
    lastRelease = releasedAt;
    instants++;
    long late = Math.min(Math.max(lateness, 0), jitter.getHighestTrackableValue());
    jitter.recordValue(late);
    cycleMax = Math.max(cycleMax, cycle);
    adaptations += applied;
    adaptationMax = Math.max(adaptationMax, adaptation);
    if (late + cycle <= period) {
      return false;
    }
    overruns++;
    if (late + cycle - adaptation <= period) {
      adaptationOverruns++;
    }
    return true;
  }

  /** Records {@code n} releases skipped. */
  public synchronized void skipped(long n) {
    skipped += n;
  }

  /** Records a cycle that failed. */
  public synchronized void failure() {
    failures++;
  }

  /** The cycles that overran so far. */
  public synchronized long overruns() {
    return overruns;
  }

  /** What was recorded so far. */
  public synchronized Figures snapshot() {
    Duration mean =
        instants < 2
            ? Duration.ZERO
            : Duration.ofNanos((lastRelease - firstRelease) / (instants - 1));
    return new Figures(
        instants,
        overruns,
        skipped,
        mean,
        Duration.ofNanos(jitter.getValueAtPercentile(50)),
        Duration.ofNanos(jitter.getValueAtPercentile(99)),
        Duration.ofNanos(jitter.getMaxValue()),
        Duration.ofNanos(cycleMax),
        adaptations,
        Duration.ofNanos(adaptationMax),
        adaptationOverruns,
        failures);
  }
}

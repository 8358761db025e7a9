package org.armgals.gals;

import java.time.Duration;
import org.HdrHistogram.Histogram;

/**
 * The figures of one island: written by the thread that runs its cycles, read by anyone
 * (synchronized; one uncontended lock per cycle).
 */
final class StatsRecorder {
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

  StatsRecorder(long period) {
    this.period = period;
  }

  /**
   * Records one cycle.
   *
   * @param releasedAt when it was released
   * @param lateness how late the release was behind its schedule
   * @param cycle from the release to the end of the cycle
   * @param adaptation the part of {@code cycle} spent applying adaptation requests
   * @param applied how many requests were applied
   */
  synchronized void record(
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
    if (late + cycle > period) {
      overruns++;
      if (late + cycle - adaptation <= period) {
        adaptationOverruns++;
      }
    }
  }

  synchronized void skipped(long n) {
    skipped += n;
  }

  synchronized void failure() {
    failures++;
  }

  synchronized IslandStats snapshot() {
    Duration mean =
        instants < 2
            ? Duration.ZERO
            : Duration.ofNanos((lastRelease - firstRelease) / (instants - 1));
    return new IslandStats(
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

package org.armgals.gals;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.armgals.active.ActiveRuntime;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * The real-time runner's schedule under each overrun policy, on a fake time source: the runner's
 * wait moves the fake time to the release, and the reaction moves it by the cycle's length.
 */
class OverrunPolicyTest {
  private static final long MS = 1_000_000;
  private final ActiveRuntime runtime = Fixtures.runtime("overrun", 2);

  @AfterEach
  void close() {
    runtime.close();
  }

  @Test
  void scheduleKeepsItsGridUnlessACycleEndsLate() {
    for (OverrunPolicy p : OverrunPolicy.values()) {
      assertThat(new Schedule(10, p).next(0, 5)).as("%s", p).isEqualTo(10);
      assertThat(new Schedule(10, p).next(0, 10)).as("%s", p).isEqualTo(10);
    }
    Schedule skip = new Schedule(10, OverrunPolicy.SKIP);
    assertThat(skip.next(0, 25)).isEqualTo(30);
    assertThat(skip.takeSkipped()).isEqualTo(2);
    assertThat(new Schedule(10, OverrunPolicy.CATCH_UP).next(0, 25)).isEqualTo(10);
    assertThat(new Schedule(10, OverrunPolicy.REPORT_ONLY).next(0, 25)).isEqualTo(25);
  }

  /** Runs five releases whose second cycle takes 25 ms of a 10 ms period; the release times. */
  private List<Long> releasesWithOneLongCycle(OverrunPolicy policy, List<IslandStats> stats) {
    FakeTime time = new FakeTime();
    List<Long> releases = new ArrayList<>();
    IslandImpl island =
        new IslandImpl(
            Island.builder("rt", runtime)
                .period(Duration.ofMillis(10))
                .overrunPolicy(policy)
                .timeSource(time),
            time.pacing());
    try (island) {
      island.spawn(
          "worker",
          0,
          c -> {
            releases.add(time.nanoTime() / MS);
            time.advance(Duration.ofMillis(c.instant() == 2 ? 25 : 2));
          });
      Schedule schedule = new Schedule(10 * MS, policy);
      long due = 10 * MS;
      for (int i = 0; i < 5; i++) {
        due = island.runOnce(schedule, due);
      }
      stats.add(island.stats());
    }
    return releases;
  }

  @Test
  void skipDropsTheMissedReleasesAndKeepsTheGrid() {
    List<IslandStats> stats = new ArrayList<>();
    assertThat(releasesWithOneLongCycle(OverrunPolicy.SKIP, stats))
        .containsExactly(10L, 20L, 50L, 60L, 70L);
    IslandStats s = stats.get(0);
    assertThat(s.overruns()).isEqualTo(1);
    assertThat(s.skipped()).isEqualTo(2);
    assertThat(s.jitterMax()).isEqualTo(Duration.ZERO);
    assertThat(s.cycleMax()).isEqualTo(Duration.ofMillis(25)); // exact: not a histogram
  }

  @Test
  void catchUpRunsTheMissedReleasesBackToBack() {
    List<IslandStats> stats = new ArrayList<>();
    assertThat(releasesWithOneLongCycle(OverrunPolicy.CATCH_UP, stats))
        .containsExactly(10L, 20L, 45L, 47L, 50L);
    IslandStats s = stats.get(0);
    // the long cycle, and the release due at 30 that ran at 45 and ended after 40
    assertThat(s.overruns()).isEqualTo(2);
    assertThat(s.skipped()).isZero();
    // HdrHistogram keeps three significant digits
    assertThat(s.jitterMax().toNanos()).isBetween(15 * MS, 15 * MS + 15 * MS / 1000);
  }

  @Test
  void reportOnlyCountsTheOverrunAndShiftsTheSchedule() {
    List<IslandStats> stats = new ArrayList<>();
    assertThat(releasesWithOneLongCycle(OverrunPolicy.REPORT_ONLY, stats))
        .containsExactly(10L, 20L, 45L, 55L, 65L);
    IslandStats s = stats.get(0);
    assertThat(s.overruns()).isEqualTo(1);
    assertThat(s.skipped()).isZero();
    assertThat(s.instants()).isEqualTo(5);
  }

  @Test
  void steppedByHandAnOverrunIsCountedWhateverThePolicy() {
    FakeTime time = new FakeTime();
    try (Island island =
        Island.builder("manual", runtime)
            .period(Duration.ofMillis(10))
            .overrunPolicy(OverrunPolicy.SKIP)
            .timeSource(time)
            .build()) {
      island.spawn("worker", 0, c -> time.advance(Duration.ofMillis(c.instant() == 2 ? 11 : 3)));
      island.step(3);
      assertThat(island.stats().instants()).isEqualTo(3);
      assertThat(island.stats().overruns()).isEqualTo(1);
      assertThat(island.stats().skipped()).isZero();
    }
  }
}

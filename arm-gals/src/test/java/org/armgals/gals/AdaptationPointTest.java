package org.armgals.gals;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.armgals.active.ActiveRuntime;
import org.armgals.kernel.AdaptationPoint;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

class AdaptationPointTest {
  private final ActiveRuntime runtime = Fixtures.runtime("adapt", 2);

  @AfterEach
  void close() {
    runtime.close();
  }

  /** A gain the main reaction reads each cycle and an adaptation changes. */
  static final class Gain {
    int gain = 1;
    final List<Integer> seen = new ArrayList<>();
  }

  private Island island(AdaptationPoint point, FakeTime time) {
    return Island.builder("i", runtime)
        .period(Duration.ofMillis(10))
        .adaptationPoint(point)
        .timeSource(time)
        .tracing(true)
        .build();
  }

  private static List<Integer> seenAfterAdaptingBeforeTheSecondCycle(Island island) {
    Gain gain = new Gain();
    ReactiveEntity<Gain> e = island.spawn("e", gain, c -> c.state().seen.add(c.state().gain));
    island.step();
    e.adapt("gain 2", g -> g.gain = 2);
    island.step(2);
    return gain.seen; // the end of a cycle happens-before step returns
  }

  @Test
  void beginOfCycleAppliesARequestBeforeTheReactionsOfTheNextCycle() {
    try (Island island = island(AdaptationPoint.BEGIN_OF_CYCLE, new FakeTime())) {
      assertThat(seenAfterAdaptingBeforeTheSecondCycle(island)).containsExactly(1, 2, 2);
      assertThat(island.trace()).contains("i 2 e adapt gain 2");
    }
  }

  @Test
  void endOfCycleAppliesARequestAfterTheReactionsOfTheNextCycle() {
    try (Island island = island(AdaptationPoint.END_OF_CYCLE, new FakeTime())) {
      assertThat(seenAfterAdaptingBeforeTheSecondCycle(island)).containsExactly(1, 1, 2);
      assertThat(island.trace()).contains("i 2 e adapt gain 2");
    }
  }

  @Test
  void adaptationTimeCountsAgainstTheCycleBudget() {
    FakeTime time = new FakeTime();
    try (Island island = island(AdaptationPoint.END_OF_CYCLE, time)) {
      ReactiveEntity<Gain> e =
          island.spawn("e", new Gain(), c -> time.advance(Duration.ofMillis(4)));
      island.step(); // 4 ms of a 10 ms budget
      e.adapt("slow", g -> time.advance(Duration.ofMillis(8)));
      island.step(); // 4 + 8 ms: over budget because of the adaptation
      island.step();

      IslandStats stats = island.stats();
      assertThat(stats.instants()).isEqualTo(3);
      assertThat(stats.adaptations()).isEqualTo(1);
      assertThat(stats.adaptationMax()).isEqualTo(Duration.ofMillis(8));
      assertThat(stats.cycleMax()).isEqualTo(Duration.ofMillis(12));
      assertThat(stats.overruns()).isEqualTo(1);
      assertThat(stats.adaptationOverruns()).isEqualTo(1);
    }
  }

  @Test
  void addedReactionsRunAfterTheOthersAndRemovedOnesStop() {
    try (Island island = island(AdaptationPoint.BEGIN_OF_CYCLE, new FakeTime())) {
      List<String> log = new ArrayList<>(); // written by the entity's thread only
      ReactiveEntity<Gain> e = island.spawn("e", new Gain(), c -> log.add("main" + c.instant()));
      e.addReaction("extra", c -> log.add("extra" + c.instant()));
      island.step();
      assertThat(e.reactions()).containsExactly("main", "extra");
      e.removeReaction("main");
      e.removeReaction("absent");
      island.step();

      assertThat(e.reactions()).containsExactly("extra");
      assertThat(log).containsExactly("main1", "extra1", "extra2");
      assertThat(island.trace()).contains("i 2 e removeReaction absent: no such reaction");
    }
  }

  @Test
  void aFailingReactionIsCountedAndTheOthersStillRun() {
    try (Island island = island(AdaptationPoint.BEGIN_OF_CYCLE, new FakeTime())) {
      Gain gain = new Gain();
      ReactiveEntity<Gain> e =
          island.spawn(
              "e",
              gain,
              c -> {
                throw new IllegalStateException("boom at " + c.instant());
              });
      e.addReaction("after", c -> c.state().seen.add((int) c.instant()));
      island.step(2);

      assertThat(island.stats().failures()).isEqualTo(2);
      assertThat(gain.seen).containsExactly(1, 2);
      assertThat(island.trace())
          .contains("i 2 e main failed: java.lang.IllegalStateException: boom at 2");
    }
  }
}

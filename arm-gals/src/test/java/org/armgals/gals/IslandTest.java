package org.armgals.gals;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.armgals.active.ActiveRuntime;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

class IslandTest {
  private final ActiveRuntime runtime = Fixtures.runtime("island", 2);

  @AfterEach
  void close() {
    runtime.close();
  }

  @Test
  void badSettingsAreRefusedNamingTheValue() {
    assertThatThrownBy(() -> Island.builder("i", runtime).period(Duration.ZERO).build())
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessage("period must be > 0, was PT0S");
    assertThatThrownBy(() -> Island.builder(" ", runtime).build())
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessage("name must not be blank, was ' '");
    assertThatThrownBy(() -> Island.builder("i", runtime).capacity(0).build())
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessage("capacity must be >= 1, was 0");
  }

  @Test
  void entityNamesAreUniqueInAnIsland() {
    try (Island island = Island.builder("i", runtime).build()) {
      island.spawn("e", 0, c -> {});
      assertThatThrownBy(() -> island.spawn("e", 1, c -> {}))
          .isInstanceOf(IllegalArgumentException.class)
          .hasMessage("entity name e is already used in island i");
      assertThat(island.entities()).extracting(ReactiveEntity::name).containsExactly("e");
    }
  }

  @Test
  void negativeCyclesAreRefused() {
    try (Island island = Island.builder("i", runtime).build()) {
      assertThatThrownBy(() -> island.step(-1))
          .isInstanceOf(IllegalArgumentException.class)
          .hasMessage("cycles must be >= 0, was -1");
    }
  }

  @Test
  void closedIslandRefusesStepsAndEntities() {
    Island island = Island.builder("i", runtime).build();
    island.close();
    island.close(); // idempotent
    assertThatThrownBy(island::step).isInstanceOf(IllegalStateException.class);
    assertThatThrownBy(() -> island.spawn("e", 0, c -> {}))
        .isInstanceOf(IllegalStateException.class)
        .hasMessage("island i is closed");
  }

  @Test
  void eventSentFromOutsideIsTakenAtTheNextRelease() {
    try (Island island = Island.builder("i", runtime).tracing(true).build()) {
      ReactiveEntity<Integer> e = island.spawn("e", 0, c -> {});
      e.send("hello");
      island.step();
      assertThat(island.trace()).containsExactly("i 1 e in [hello]");
    }
  }

  @Test
  void startedIslandReleasesOnRealTimeAndReportsItsFigures() throws InterruptedException {
    CountDownLatch twenty = new CountDownLatch(20);
    Island island = Island.builder("rt", runtime).period(Duration.ofMillis(1)).build();
    try {
      island.spawn("e", 0, c -> twenty.countDown());
      island.start();
      island.start(); // idempotent
      assertThat(twenty.await(10, TimeUnit.SECONDS)).isTrue();
      assertThatThrownBy(island::step)
          .isInstanceOf(IllegalStateException.class)
          .hasMessage("island rt is started; it cannot be stepped");
    } finally {
      island.close();
    }
    IslandStats stats = island.stats();
    assertThat(stats.instants()).isGreaterThanOrEqualTo(20);
    assertThat(stats.meanPeriod()).isPositive();
    assertThat(stats.jitterMax()).isGreaterThanOrEqualTo(stats.jitterP99());
    assertThat(stats.jitterP99()).isGreaterThanOrEqualTo(stats.jitterP50());
  }
}

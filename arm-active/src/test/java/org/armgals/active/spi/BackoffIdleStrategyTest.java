package org.armgals.active.spi;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.armgals.active.spi.BackoffIdleStrategy.Phase;
import org.junit.jupiter.api.Test;

/** The backoff strategy's contract: its phases in order, its parks doubling, and reset. */
class BackoffIdleStrategyTest {

  private final List<Long> parks = new ArrayList<>();

  private BackoffIdleStrategy strategy(long spins, long yields, long minPark, long maxPark) {
    return new BackoffIdleStrategy(
        spins, yields, Duration.ofNanos(minPark), Duration.ofNanos(maxPark), parks::add);
  }

  @Test
  void spinsThenYieldsThenParksLongerEachTimeUpToTheLongestPark() {
    BackoffIdleStrategy s = strategy(3, 2, 1_000, 5_000);
    assertThat(s.phase()).isEqualTo(Phase.NOT_IDLE);
    List<Phase> seen = new ArrayList<>();
    for (int i = 0; i < 10; i++) {
      s.idle(0);
      seen.add(s.phase());
    }
    assertThat(seen.subList(0, 3)).containsOnly(Phase.SPINNING); // three spins
    assertThat(seen.subList(3, 5)).containsOnly(Phase.YIELDING); // two yields
    assertThat(seen.subList(5, 10)).containsOnly(Phase.PARKING);
    assertThat(parks).containsExactly(1_000L, 2_000L, 4_000L, 5_000L, 5_000L);
  }

  @Test
  void workResetsItToSpinningAndTheShortestPark() {
    BackoffIdleStrategy s = strategy(1, 1, 1_000, 8_000);
    for (int i = 0; i < 5; i++) {
      s.idle();
    }
    assertThat(s.phase()).isEqualTo(Phase.PARKING);
    assertThat(s.nextParkNanos()).isEqualTo(8_000);
    s.idle(1); // work was done
    assertThat(s.phase()).isEqualTo(Phase.NOT_IDLE);
    assertThat(s.nextParkNanos()).isEqualTo(1_000);
    parks.clear();
    s.idle(0);
    assertThat(s.phase()).isEqualTo(Phase.SPINNING);
    s.idle(0);
    s.idle(0);
    assertThat(parks).containsExactly(1_000L);
  }

  @Test
  void resetStartsAgainFromTheFirstPhase() {
    BackoffIdleStrategy s = strategy(2, 0, 10, 10);
    s.idle();
    s.idle();
    s.idle();
    assertThat(parks).containsExactly(10L);
    s.reset();
    s.idle();
    s.idle();
    assertThat(parks).containsExactly(10L); // spinning again, no new park
    assertThat(s.phase()).isEqualTo(Phase.SPINNING);
  }

  @Test
  void phasesOfNoStepsAreSkipped() {
    BackoffIdleStrategy s = strategy(0, 0, 100, 100);
    s.idle();
    assertThat(s.phase()).isEqualTo(Phase.PARKING);
    s.idle();
    assertThat(parks).containsExactly(100L, 100L);
  }

  @Test
  void aLongestParkOfMoreThanLongMaxNanosSaturates() {
    BackoffIdleStrategy s =
        new BackoffIdleStrategy(
            0,
            0,
            Duration.ofNanos(Long.MAX_VALUE / 2 + 1),
            Duration.ofDays(365L * 1_000_000),
            parks::add);
    s.idle();
    s.idle();
    s.idle();
    assertThat(parks).containsExactly(Long.MAX_VALUE / 2 + 1, Long.MAX_VALUE, Long.MAX_VALUE);
  }

  @Test
  void badArgumentsAreNamed() {
    Duration ms = Duration.ofMillis(1);
    assertThatThrownBy(() -> IdleStrategy.backoff(-1, 0, ms, ms))
        .hasMessage("maxSpins must be >= 0, was -1");
    assertThatThrownBy(() -> IdleStrategy.backoff(0, -2, ms, ms))
        .hasMessage("maxYields must be >= 0, was -2");
    assertThatThrownBy(() -> IdleStrategy.backoff(0, 0, Duration.ZERO, ms))
        .hasMessage("minPark must be > 0, was PT0S");
    assertThatThrownBy(() -> IdleStrategy.backoff(0, 0, ms, Duration.ofNanos(1)))
        .hasMessage("maxPark must be >= minPark (PT0.001S), was PT0.000000001S");
  }
}

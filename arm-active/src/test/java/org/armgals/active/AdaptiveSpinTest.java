package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The workers' spin: it lengthens while it finds work, shrinks while it does not, learns from work
 * that came soon after a block, and says when it is in its last quarter. Time is a field the test
 * moves.
 */
class AdaptiveSpinTest {

  private long now;
  private final List<Long> parks = new ArrayList<>();

  private AdaptiveSpin spin(long min, long max, long first) {
    return new AdaptiveSpin(() -> now, min, max, first, parks::add);
  }

  /**
   * Spins with the time standing still, then moves it past the spin's end: the next step, which
   * reads the clock, says block.
   */
  private static void spinsUntilItRunsOut(AdaptiveSpin s, Runnable passTheEnd) {
    for (int step = 0; step < 4; step++) {
      assertThat(s.spin()).isTrue();
    }
    passTheEnd.run();
    assertThat(s.spin()).isFalse();
  }

  /** One step, which reads the clock. */
  private static void spinToTheNextClockReading(AdaptiveSpin s) {
    assertThat(s.spin()).isTrue();
  }

  @Test
  void spinsUntilItsTimeRunsOutThenSaysBlockUntilReset() {
    AdaptiveSpin s = spin(1_000, 100_000, 8_000);
    spinsUntilItRunsOut(s, () -> now += 8_000);
    assertThat(s.spin()).isFalse();
    assertThat(s.spin()).isFalse(); // it keeps saying block
    s.reset();
    assertThat(s.spin()).isTrue(); // a new wait
  }

  @Test
  void aSpinThatFindsWorkDoublesTheNextAndOneThatRunsOutHalvesIt() {
    AdaptiveSpin s = spin(1_000, 16_000, 8_000);
    assertThat(s.spin()).isTrue();
    s.reset(); // found work while spinning
    assertThat(s.spinNanos()).isEqualTo(16_000);
    assertThat(s.spin()).isTrue();
    s.reset();
    assertThat(s.spinNanos()).isEqualTo(16_000); // the longest
    for (long expected : new long[] {8_000, 4_000, 2_000, 1_000, 1_000}) {
      spinsUntilItRunsOut(s, () -> now += 16_000);
      s.reset(); // work came later, after a block
      assertThat(s.spinNanos()).isEqualTo(expected);
    }
  }

  @Test
  void workSoonAfterABlockDoublesTheLastSpinThatRanOut() {
    AdaptiveSpin s = spin(1_000, 100_000, 40_000);
    spinsUntilItRunsOut(s, () -> now += 40_000);
    assertThat(s.spinNanos()).isEqualTo(20_000);
    s.blockedFor(3_000); // work 3 µs after the block: a 40 µs spin was too short
    assertThat(s.spinNanos()).isEqualTo(80_000);
    spinsUntilItRunsOut(s, () -> now += 80_000);
    s.blockedFor(100_000); // not within the longest spin: teaches nothing
    assertThat(s.spinNanos()).isEqualTo(40_000);
    assertThat(s.spin()).isTrue();
    s.reset(); // found work: 80 µs next
    spinsUntilItRunsOut(s, () -> now += 80_000);
    s.blockedFor(1_000); // twice 80 µs
    assertThat(s.spinNanos()).isEqualTo(100_000); // the longest
  }

  @Test
  void saysLateFromTheLastQuarterOfItsSpin() {
    AdaptiveSpin s = spin(1_000, 100_000, 8_000);
    assertThat(s.spin()).isTrue();
    spinToTheNextClockReading(s);
    assertThat(s.late()).isFalse();
    now += 5_999; // 2,001 ns left: more than a quarter
    spinToTheNextClockReading(s);
    assertThat(s.late()).isFalse();
    now += 1; // 2,000 left: the last quarter
    spinToTheNextClockReading(s);
    assertThat(s.late()).isTrue();
    s.reset();
    assertThat(s.spin()).isTrue();
    assertThat(s.late()).isFalse(); // a new spin starts early
  }

  @Test
  void idleParksOnceTheSpinRanOutLongerEachTimeUpToTheLongestSpin() {
    AdaptiveSpin s = spin(1_000, 4_000, 1_000);
    s.idle();
    now += 1_000;
    for (int i = 0; i < 4; i++) {
      s.idle();
    }
    assertThat(parks).containsExactly(1_000L, 2_000L, 4_000L, 4_000L);
    s.idle(1); // work: the next wait spins again
    parks.clear();
    s.idle(0);
    assertThat(parks).isEmpty();
  }

  @Test
  void badSpinsAreNamed() {
    assertThatThrownBy(() -> spin(0, 10, 10))
        .hasMessage("spins must be 0 < min <= max, were 0 and 10");
    assertThatThrownBy(() -> spin(10, 5, 5))
        .hasMessage("spins must be 0 < min <= max, were 10 and 5");
  }
}

package org.armgals.active.spi;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The deadline pacer's contract, on a time moved by the test: parks and spins are steps. */
class DeadlinePacerTest {

  /** A time that parks and spins move: a park of n moves it by a fraction of n, or more. */
  private static final class SteppedTime {
    long now;
    final List<Long> parks = new ArrayList<>();
    int reads;
    long spinStep = 1_000;

    long read() {
      reads++;
      return now;
    }
  }

  @ParameterizedTest(name = "a park moves time by {0}% of its length")
  @ValueSource(ints = {0, 1, 50, 99, 100, 150, 1_000})
  void neverReturnsBeforeItsDeadlineHoweverLongParksLast(int percent) {
    SteppedTime t = new SteppedTime();
    DeadlinePacer pacer =
        DeadlinePacer.of(
            () -> {
              long n = t.read();
              t.now += t.spinStep; // time moves on between reads (spinning)
              return n;
            },
            Duration.ofNanos(100_000),
            nanos -> {
              t.parks.add(nanos);
              t.now += nanos * percent / 100;
            });
    long due = 5_000_000;
    assertThat(pacer.awaitUntil(due, () -> false)).isTrue();
    assertThat(t.now).isGreaterThanOrEqualTo(due);
    assertThat(t.parks).allSatisfy(p -> assertThat(p).isPositive());
  }

  @Test
  void parksUntilTheSpinMarginThenSpinsTheRest() {
    long[] now = {0};
    List<Long> parks = new ArrayList<>();
    int[] spins = {0};
    DeadlinePacer pacer =
        DeadlinePacer.of(
            () -> {
              long n = now[0];
              if (!parks.isEmpty()) {
                spins[0]++;
                now[0] += 10_000; // each spin after the park: 10 µs
              }
              return n;
            },
            Duration.ofNanos(100_000),
            nanos -> {
              parks.add(nanos);
              now[0] += nanos;
            });
    pacer.awaitUntil(1_000_000);
    assertThat(parks).containsExactly(900_000L); // one park, to 100 µs before the deadline
    assertThat(now[0]).isGreaterThanOrEqualTo(1_000_000);
    assertThat(spins[0]).isBetween(10, 12); // the last 100 µs spun, in steps of 10 µs
  }

  @Test
  void aZeroSpinMarginParksOnly() {
    long[] now = {0};
    List<Long> parks = new ArrayList<>();
    DeadlinePacer pacer =
        DeadlinePacer.of(
            () -> now[0],
            Duration.ZERO,
            nanos -> {
              parks.add(nanos);
              now[0] += (nanos + 1) / 2; // every park wakes half way
            });
    pacer.awaitUntil(1_000);
    assertThat(now[0]).isGreaterThanOrEqualTo(1_000);
    assertThat(parks).startsWith(1_000L, 500L, 250L);
  }

  @Test
  void aDeadlineAlreadyPastReturnsAtOnceWithoutParking() {
    List<Long> parks = new ArrayList<>();
    DeadlinePacer pacer = DeadlinePacer.of(() -> 2_000, Duration.ZERO, parks::add);
    assertThat(pacer.awaitUntil(2_000, () -> true)).isTrue();
    assertThat(pacer.awaitUntil(1_000, () -> true)).isTrue();
    assertThat(parks).isEmpty();
  }

  @Test
  void stopEndsTheWaitBeforeTheDeadline() {
    long[] now = {0};
    int[] parks = {0};
    DeadlinePacer pacer =
        DeadlinePacer.of(
            () -> now[0],
            Duration.ZERO,
            nanos -> {
              parks[0]++;
              now[0] += 100; // short wakes: the stop is seen between them
            });
    assertThat(pacer.awaitUntil(1_000_000, () -> parks[0] == 3)).isFalse();
    assertThat(parks[0]).isEqualTo(3);
    assertThat(now[0]).isLessThan(1_000_000);
  }

  @Test
  void badArgumentsAreNamed() {
    assertThatThrownBy(() -> DeadlinePacer.of(() -> 0, Duration.ofNanos(-1)))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("spin margin must be >= 0, was PT-0.000000001S");
    assertThat(DeadlinePacer.of(() -> 0).spin()).isEqualTo(DeadlinePacer.DEFAULT_SPIN);
  }
}

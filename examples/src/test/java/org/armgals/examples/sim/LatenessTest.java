package org.armgals.examples.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class LatenessTest {
  private static final long PERIOD = 10_000_000;

  @Test
  void aCycleIsMissedOnlyWhenItEndsMoreThanAPeriodBehind() {
    Lateness lateness = new Lateness(PERIOD);
    lateness.ended(1, PERIOD);
    lateness.ended(2, -PERIOD);

    assertThat(lateness.missed()).isZero();
    assertThat(lateness.entry()).isEmpty();

    lateness.ended(3, PERIOD + 1);
    assertThat(lateness.missed()).isEqualTo(1);
  }

  @Test
  void missedCyclesInARowAreOneSpellAndTheFurthestBehindIsNamed() {
    Lateness lateness = new Lateness(PERIOD);
    lateness.ended(10, 45_000_000); // a stall: this cycle and the next ones catch up
    lateness.ended(11, 30_000_000);
    lateness.ended(12, 15_000_000);
    lateness.ended(13, 0);
    lateness.ended(500, 12_000_000); // a second, shorter one

    assertThat(lateness.missed()).isEqualTo(4);
    assertThat(lateness.entry())
        .hasValueSatisfying(
            e -> {
              assertThat(e.name()).isEqualTo("late spells");
              assertThat(e.value())
                  .isEqualTo(
                      "2 (runs of missed cycles); the furthest behind 45.0 ms, at cycle 10"
                          + " (0.10 s)");
            });
  }
}

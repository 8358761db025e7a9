package org.armgals.gals;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.armgals.active.ActiveRuntime;
import org.armgals.active.ManualClock;
import org.armgals.testkit.ActiveTest;
import org.armgals.testkit.Probe;
import org.armgals.testkit.Stepper;
import org.junit.jupiter.api.Test;

/**
 * An island, a probe and the test's manual clock stepped together by the testkit's {@link Stepper}
 * (docs/testing.md quotes the first test).
 */
@ActiveTest(manualClock = true)
class SteppedIslandTest {

  @Test
  void anIslandAndAProbeSteppedTogether(ActiveRuntime runtime, ManualClock clock) {
    // tag::island[]
    try (Island island = Island.builder("counters", runtime).jmx(false).build()) {
      // each instant: the island's cycle, then the clock's release (the probe's)
      Stepper stepper = Stepper.of(clock).and(island::step);
      Probe probe = Probe.create(runtime, stepper);
      int[] count = {0};
      island.spawn(
          "counter",
          count,
          c -> {
            if (++c.state()[0] == 3) {
              c.emit(probe.address(), "three");
            }
          });

      Emission three = probe.expectMessageType(Emission.class, 5);
      assertThat(three.payload()).isEqualTo("three");
      assertThat(stepper.instant()).isEqualTo(3);

      stepper.stepUntil("the counter at 10", () -> count[0] >= 10, 20);
      assertThat(stepper.instant()).isEqualTo(10);
    }
    // end::island[]
  }

  @Test
  void aConditionThatNeverHoldsFailsNamingItAndTheInstants(
      ActiveRuntime runtime, ManualClock clock) {
    try (Island island = Island.builder("counters", runtime).jmx(false).build()) {
      Stepper stepper = Stepper.of(clock).and(island::step);
      int[] count = {0};
      island.spawn("counter", count, c -> c.state()[0]++);
      assertThatThrownBy(() -> stepper.stepUntil("the counter at 100", () -> count[0] >= 100, 4))
          .isInstanceOf(AssertionError.class)
          .hasMessage("the counter at 100 did not hold within 4 instant(s) (instants 1 to 4)");
      assertThat(island.instant()).isEqualTo(4);
    }
  }
}

package org.armgals.testkit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.armgals.active.Clock;
import org.armgals.active.ManualClock;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

class StepperTest {
  final ManualClock clock = Clock.manual(Duration.ofMillis(10));
  final List<String> order = new ArrayList<>();

  @AfterEach
  void closeClock() {
    clock.close();
  }

  long island(String name) {
    order.add(name + "@" + (clock.instant() + 1));
    return clock.instant() + 1;
  }

  @Test
  void eachInstantStepsTheIslandsInOrderThenTheClock() {
    Stepper stepper = Stepper.of(clock).and(() -> island("east")).and(() -> island("west"));
    assertThat(stepper.step()).isEqualTo(1);
    stepper.step(2);
    assertThat(stepper.instant()).isEqualTo(3);
    assertThat(order).containsExactly("east@1", "west@1", "east@2", "west@2", "east@3", "west@3");
  }

  @Test
  void andGivesANewStepperAndLeavesThisOneAsItWas() {
    Stepper alone = Stepper.of(clock);
    Stepper withIsland = alone.and(() -> island("east"));
    alone.step();
    assertThat(order).isEmpty();
    withIsland.step();
    assertThat(order).containsExactly("east@2");
  }

  @Test
  void stepUntilStopsAtTheFirstInstantTheConditionHolds() {
    Stepper stepper = Stepper.of(clock);
    assertThat(stepper.stepUntil(() -> clock.instant() >= 4, 10)).isEqualTo(4);
    assertThat(stepper.stepUntil(() -> true, 10)).as("holds at once: no step").isZero();
    assertThat(clock.instant()).isEqualTo(4);
  }

  @Test
  void stepUntilFailsNamingTheConditionAndTheInstantsItStepped() {
    Stepper stepper = Stepper.of(clock);
    stepper.step(2);
    assertThatThrownBy(() -> stepper.stepUntil("the robot at rest", () -> false, 5))
        .isInstanceOf(AssertionError.class)
        .hasMessage("the robot at rest did not hold within 5 instant(s) (instants 3 to 7)");
    assertThat(clock.instant()).isEqualTo(7);
  }

  @Test
  void badCountsAreRefusedNamingTheValue() {
    Stepper stepper = Stepper.of(clock);
    assertThatThrownBy(() -> stepper.step(-1)).hasMessage("instants must be >= 0, was -1");
    assertThatThrownBy(() -> stepper.stepUntil(() -> false, -2))
        .hasMessage("maxInstants must be >= 0, was -2");
    assertThatThrownBy(() -> Stepper.of(null)).hasMessage("clock");
  }
}

package org.armgals.kernel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import org.armgals.active.Clock;
import org.armgals.active.ManualClock;
import org.armgals.active.ObjectConfig;
import org.junit.jupiter.api.Test;

/** A reactive (synchronous) entity applies adaptations at the point of its cycle it chose. */
class AdaptationPointTest extends KernelFixture {

  /** A reactive robot, attached to its meta at the clock's first release. */
  private Entity reactiveRobot(ManualClock clock, BehavioralMeta meta, AdaptationPoint point) {
    Entity robot =
        robotKind()
            .newEntity(
                "robot",
                meta,
                EntityOptions.defaults()
                    .withConfig(ObjectConfig.synchronous(clock))
                    .withNotification(NotificationPolicy.actionsOnly())
                    .withAdaptationPoint(point));
    clock.step();
    assertThat(robot.behavioralMeta()).containsSame(meta);
    return robot;
  }

  @Test
  void endOfCycleAppliesAnAdaptationAfterTheEventsOfItsInstant() {
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    Recorder policy = new Recorder();
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", policy, Damping.none());
    Entity robot = reactiveRobot(clock, meta, AdaptationPoint.END_OF_CYCLE);

    meta.adapt(robot, new Adaptation.ApplyBehavior("eco", null)).getValue();
    robot.send("work", 0.1);
    clock.step();
    drain(meta);

    assertThat(policy.of(ActionEvent.class))
        .extracting(ActionEvent::behavior)
        .containsExactly("work", "eco");
    assertThat(meta.model(robot).getValue().appliedVersion()).isEqualTo(1);
  }

  @Test
  void beginOfCycleAppliesAnAdaptationAtTheStartOfTheNextInstant() {
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", new Recorder(), Damping.none());
    Entity robot = reactiveRobot(clock, meta, AdaptationPoint.BEGIN_OF_CYCLE);

    meta.adapt(robot, new Adaptation.ApplyBehavior("eco", null)).getValue();
    clock.step();
    assertThat(robot.state().observe()).containsEntry("mode", "normal");
    clock.step();
    assertThat(robot.state().observe()).containsEntry("mode", "eco");
    assertThat(robot.appliedVersion()).isEqualTo(1);
  }

  @Test
  void anAsynchronousEntityCanOnlyAdaptOnArrival() {
    assertThatThrownBy(
            () -> EntityOptions.defaults().withAdaptationPoint(AdaptationPoint.END_OF_CYCLE))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("END_OF_CYCLE")
        .hasMessageContaining("ASYNCHRONOUS");
  }
}

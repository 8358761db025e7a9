package org.armgals.kernel;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import org.armgals.kernel.spi.MetaPolicy;
import org.junit.jupiter.api.Test;

/** An oscillating input does not make a damped meta thrash. */
class AntiThrashingTest extends KernelFixture {
  static final Threshold LOW = new Threshold("low", "battery", 0.25, 0.35);

  /** Eco mode below the band, normal mode above it: one adaptation per crossing, if allowed. */
  static final MetaPolicy FOLLOW_CROSSINGS =
      (ctx, n) -> {
        if (n instanceof ThresholdEvent t) {
          ctx.adapt(t.entity(), new Adaptation.ApplyBehavior(t.below() ? "eco" : "normal", null));
        }
      };

  /** Swings the battery {@code swings} times by {@code amplitude}, 100 ms apart. */
  private ModelView oscillate(Damping damping, double start, double amplitude, int swings) {
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", FOLLOW_CROSSINGS, damping);
    Entity robot =
        robotKind()
            .newEntity(
                "robot",
                meta,
                EntityOptions.defaults()
                    .withNotification(NotificationPolicy.quiet().watching(LOW)));
    robot.call("work", round(1 - start)).getValue();
    for (int i = 0; i < swings; i++) {
      time.advance(Duration.ofMillis(100));
      robot.call(i % 2 == 0 ? "work" : "charge", amplitude).getValue();
      settle(robot, meta, 1);
    }
    settle(robot, meta, 1);
    return meta.model(robot).getValue();
  }

  @Test
  void withoutDampingEveryCrossingAdaptsTheRobot() {
    ModelView model = oscillate(Damping.none(), 0.5, 0.3, 40);
    assertThat(model.requestedVersion()).isEqualTo(40);
  }

  @Test
  void dwellTimeAndRateLimitHoldBackAdaptationsOfAnOscillatingInput() {
    Damping damping = new Damping(Duration.ofSeconds(1), 3, Duration.ofSeconds(10));
    ModelView model = oscillate(damping, 0.5, 0.3, 40); // 4 s of swings every 100 ms

    assertThat(model.requestedVersion()).isEqualTo(3); // t = 0.1 s, 1.1 s, 2.1 s; then the rate
    assertThat(model.suppressedAdaptations()).isEqualTo(37);
    assertThat(model.appliedVersion()).isEqualTo(3);
  }

  @Test
  void hysteresisIgnoresAnOscillationInsideTheBand() {
    ModelView model = oscillate(Damping.none(), 0.32, 0.04, 40); // 0.28 <-> 0.32
    assertThat(model.requestedVersion()).isZero();
    assertThat(model.suppressedAdaptations()).isZero();
  }
}

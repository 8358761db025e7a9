package org.armgals.kernel;

import static org.assertj.core.api.Assertions.assertThat;

import org.armgals.kernel.spi.MetaContext;
import org.armgals.kernel.spi.MetaPolicy;
import org.junit.jupiter.api.Test;

/**
 * The paper's battery example (§2.3): the meta ignores the battery level until a meta-event marks a
 * threshold crossing, then solicits the level at a fine grain and adapts the robot; when the
 * battery is charged again, it goes back to ignoring it.
 */
class BatteryExampleTest extends KernelFixture {
  static final Threshold LOW = new Threshold("low", "battery", 0.25, 0.35);
  static final String THRESHOLDS_ONLY = "kind = 'threshold'";
  static final String LOW_BATTERY = "kind = 'threshold' OR (kind = 'state' AND battery < 0.2)";
  static final NotificationPolicy IGNORE_BATTERY = NotificationPolicy.quiet().watching(LOW);
  static final NotificationPolicy FOLLOW_BATTERY =
      NotificationPolicy.statesOnly().observing("battery").watching(LOW);

  /** The energy meta of the example. */
  static final class Energy implements MetaPolicy {
    @Override
    public void onNotification(MetaContext ctx, Notification n) {
      switch (n) {
        case ThresholdEvent t when t.below() -> {
          ctx.setFilter(t.entity(), LOW_BATTERY);
          ctx.adapt(t.entity(), new Adaptation.SetNotification(FOLLOW_BATTERY));
        }
        case ThresholdEvent t -> {
          ctx.setFilter(t.entity(), THRESHOLDS_ONLY);
          ctx.adapt(t.entity(), new Adaptation.SetNotification(IGNORE_BATTERY));
          ctx.adapt(t.entity(), new Adaptation.ApplyBehavior("normal", null));
        }
        case StateEvent s when s.observation().get("battery") instanceof Double b && b < 0.2 ->
            ctx.adapt(s.entity(), new Adaptation.ApplyBehavior("eco", null));
        default -> {}
      }
    }
  }

  @Test
  void theMetaFollowsTheBatteryOnlyWhileItIsLow() {
    Recorder energy = new Recorder(new Energy());
    BehavioralMeta meta = kernel.newBehavioralMeta("energy", energy, Damping.none());
    Entity robot =
        robotKind()
            .newEntity("robot", meta, EntityOptions.defaults().withNotification(IGNORE_BATTERY));
    meta.setFilter(robot, THRESHOLDS_ONLY).touch();
    int attached = energy.seen.size();

    for (int i = 0; i < 3; i++) {
      robot.call("work", 0.2).getValue(); // 0.8, 0.6, 0.4: ignored
    }
    robot.call("work", 0.1).getValue(); // 0.3: inside the band, no crossing
    settle(robot, meta, 2);
    assertThat(energy.seen).hasSize(attached);

    robot.call("work", 0.1).getValue(); // 0.2: below the band, the meta starts following
    settle(robot, meta, 3);
    assertThat(energy.of(ThresholdEvent.class))
        .singleElement()
        .satisfies(
            t -> {
              assertThat(t.below()).isTrue();
              assertThat(t.value()).isEqualTo(0.2);
            });
    assertThat(robot.notificationPolicy()).isEqualTo(FOLLOW_BATTERY);
    assertThat(meta.model(robot).getValue().filter()).isEqualTo(LOW_BATTERY);
    assertThat(robot.state().observe()).containsEntry("mode", "normal");

    robot.call("work", 0.05).getValue(); // 0.15: under 0.2, the meta puts the robot in eco mode
    settle(robot, meta, 3);
    assertThat(robot.state().observe()).containsEntry("mode", "eco");
    assertThat(energy.of(StateEvent.class).getLast().observation()).containsEntry("battery", 0.15);

    robot.call("charge", 0.5).getValue(); // 0.65: above the band, back to ignoring the battery
    settle(robot, meta, 3);
    assertThat(robot.state().observe()).containsEntry("mode", "normal");
    assertThat(robot.notificationPolicy()).isEqualTo(IGNORE_BATTERY);
    int charged = energy.seen.size();

    robot.call("work", 0.1).getValue();
    settle(robot, meta, 2);
    assertThat(energy.seen).hasSize(charged);
    ModelView model = meta.model(robot).getValue();
    assertThat(model.filter()).isEqualTo(THRESHOLDS_ONLY);
    assertThat(model.appliedVersion()).isEqualTo(4).isEqualTo(robot.appliedVersion());
  }
}

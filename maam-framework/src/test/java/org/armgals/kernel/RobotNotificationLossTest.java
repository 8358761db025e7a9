package org.armgals.kernel;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.ShutdownMode;
import org.armgals.gals.Island;
import org.armgals.kernel.spi.MetaContext;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.Outputs;
import org.armgals.maam.Perceptor;
import org.armgals.maam.Port;
import org.armgals.maam.RobotKind;
import org.armgals.maam.Schema;
import org.armgals.maam.TestBody;
import org.armgals.maam.spi.Body;
import org.armgals.representation.p.PState;
import org.junit.jupiter.api.Test;

/**
 * A robot's notifications lost on their way (as at-most-once delivery across runtimes may): the
 * meta's model sees the gap in the numbers and asks the robot for a fresh state, from which it goes
 * on (paper §3.3: state events are robust to loss). In this package to reach the kernel's loss
 * hook.
 */
class RobotNotificationLossTest {

  /** A perceptor that perceives nothing. */
  private static final class Idle implements Perceptor {
    @Override
    public String name() {
      return "idle";
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of();
    }

    @Override
    public void perceive(Body body, Outputs out) {}
  }

  @Test
  void aGapInARobotsNotificationsMakesItsMetaResynchronize() {
    ActiveRuntime runtime = ActiveRuntime.builder().workers(2).jmx(false).build();
    try (Kernel kernel =
            StructuralMeta.bootstrap(runtime, KernelOptions.defaults().withJmx(false));
        Island island = Island.builder("robots", runtime).jmx(false).build()) {
      long[] now = {0};
      AbstractRobot robot = new AbstractRobot("lossy", TestBody.empty("body"), () -> now[0]) {};
      robot.addSchema(Schema.builder("idle").add(new Idle()).build());
      BMetaRobot meta =
          new BMetaRobot("bmrobot", Damping.none()) {
            @Override
            public void onNotification(MetaContext context, Notification n) {}
          };
      meta.start(kernel);
      StructuralMeta<PState> kind = RobotKind.define(kernel, "Lossy", robot.observation());
      robot.start(
          island,
          kind,
          meta,
          island
              .entityOptions()
              .withNotification(NotificationPolicy.actionsOnly())
              .withLockStep(1, Duration.ofSeconds(30)));
      island.step(5);
      ((EntityImpl<?>) robot.handle()).servant.loseNotifications(2);
      island.step(4);
      meta.model(robot).getValue();
      island.step(3); // the resynchronization request is taken, the fresh state integrated

      ModelView model = meta.model(robot).getValue();
      assertThat(model.resyncRequests()).isGreaterThanOrEqualTo(1);
      assertThat(model.resyncing()).isFalse();
      assertThat(((PState) model.state()).fields())
          .containsEntry("cycle", 12L)
          .containsEntry("schemas", List.of("idle"));
      assertThat(Map.copyOf(((PState) model.state()).fields())).isEqualTo(robot.state().observe());
    } finally {
      runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5));
    }
  }
}

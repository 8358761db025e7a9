package org.armgals.maam;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicBoolean;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.ShutdownMode;
import org.armgals.gals.Island;
import org.armgals.kernel.AdaptationPoint;
import org.armgals.kernel.BehavioralMeta;
import org.armgals.kernel.Damping;
import org.armgals.kernel.Entity;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.ModelView;
import org.armgals.kernel.NotificationPolicy;
import org.armgals.kernel.StateEvent;
import org.armgals.kernel.StructuralMeta;
import org.armgals.kernel.spi.MetaPolicy;
import org.armgals.representation.p.PState;
import org.junit.jupiter.api.Test;

/**
 * A robot is a kernel entity and its meta a behavioral meta-entity (paper figure 8): the robot's
 * cycle notifies the meta, which runs on its own object, models the robot from the notifications,
 * and adapts it by versioned requests applied at the island's adaptation point, in lock step
 * exactly {@code k} cycles after the cycle they were decided on.
 */
class RobotAsKernelEntityTest {

  /** What one run of the linked robot and its meta gave. */
  record Run(List<Integer> sums, ModelView model, List<Boolean> metaInsideCycle) {}

  /**
   * Runs the linked robot for {@code cycles} cycles on an island (adapting at its beginning) with a
   * meta that, on the notification of cycle 3, asks for {@code change}.
   */
  private static Run run(int workers, int latency, int cycles, Adaptation change) {
    ActiveRuntime runtime = ActiveRuntime.builder().workers(workers).jmx(false).build();
    try (Kernel kernel = org.armgals.kernel.StructuralMeta.bootstrap(runtime);
        Island island =
            Island.builder("robots", runtime)
                .adaptationPoint(AdaptationPoint.BEGIN_OF_CYCLE)
                .jmx(false)
                .build()) {
      TestRobot.TestTime time = new TestRobot.TestTime();
      LinkedRobot robot = LinkedRobot.create("r", time);
      StructuralMeta<PState> kind = RobotKind.define(kernel, "LinkedRobot", robot.observation());
      AtomicBoolean asked = new AtomicBoolean();
      List<Boolean> insideCycle = new CopyOnWriteArrayList<>();
      MetaPolicy policy =
          (context, n) -> {
            insideCycle.add(robot.inCycle());
            if (n instanceof StateEvent s
                && Long.valueOf(3).equals(s.observation().get("cycle"))
                && asked.compareAndSet(false, true)) {
              context.adapt(s.entity(), RobotKind.request(change));
            }
          };
      BehavioralMeta meta = kernel.newBehavioralMeta("bmrobot", policy, Damping.none());
      Entity entity =
          robot.start(
              island,
              kind,
              meta,
              island
                  .entityOptions()
                  .withNotification(NotificationPolicy.statesOnly())
                  .withLockStep(latency, Duration.ofSeconds(10)));
      island.step(cycles);
      island.step(); // the acknowledgement of the last adaptation, if any, is sent by now
      ModelView model = meta.model(entity).getValue();
      assertThat(robot.kernelEntity()).containsSame(entity);
      return new Run(List.copyOf(robot.sums), model, List.copyOf(insideCycle));
    } finally {
      runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5));
    }
  }

  private static Adaptation biasFive() {
    return new Adaptation.ChangeModule(
        LinkedRobot.create("prototype", new TestRobot.TestTime()).inbox(5));
  }

  @Test
  void aChangeDecidedOnCycleThreeIsAppliedAtTheAdaptationPointOfCycleThreePlusK() {
    assertThat(run(2, 1, 8, biasFive()).sums()).containsExactly(0, 0, 0, 5, 5, 5, 5, 5, 5);
    assertThat(run(2, 2, 8, biasFive()).sums()).containsExactly(0, 0, 0, 0, 5, 5, 5, 5, 5);
  }

  @Test
  void lockStepRunsAreTheSameWhateverTheNumberOfWorkers() {
    Run one = run(1, 1, 30, biasFive());
    Run four = run(4, 1, 30, biasFive());

    assertThat(one.sums()).hasSize(31).isEqualTo(four.sums());
  }

  @Test
  void theMetaModelsTheRobotFromItsNotificationsAndNeverRunsInItsCycle() {
    Run run = run(2, 1, 8, biasFive());

    assertThat(run.model().state())
        .isEqualTo(new PState(Map.of("cycle", 9L, "program", 2L, "errors", 0L)));
    assertThat(run.model().lastSeq()).isEqualTo(10); // the attachment's snapshot, then 9 cycles
    assertThat(run.model().requestedVersion()).isEqualTo(1);
    assertThat(run.model().appliedVersion()).isEqualTo(1);
    assertThat(run.model().lockStep()).isTrue();
    assertThat(run.metaInsideCycle()).hasSize(10).containsOnly(false);
  }

  @Test
  void aRefusedChangeIsAcknowledgedAsRefusedAndTheRobotRunsOn() {
    Adaptation unknown = new Adaptation.RemoveSchema("no-such-schema");
    Run run = run(2, 1, 8, unknown);

    assertThat(run.sums()).containsOnly(0).hasSize(9);
    assertThat(run.model().appliedVersion()).isZero();
    assertThat(run.model().refusedAdaptations()).isEqualTo(1);
    assertThat(run.model().lastRefusal()).contains("no-such-schema");
  }

  @Test
  void aRobotRunningAsAKernelEntityIsNotSteppedByHand() {
    ActiveRuntime runtime = ActiveRuntime.builder().workers(1).jmx(false).build();
    try (Kernel kernel = org.armgals.kernel.StructuralMeta.bootstrap(runtime);
        Island island = Island.builder("robots", runtime).jmx(false).build()) {
      LinkedRobot robot = LinkedRobot.create("r", new TestRobot.TestTime());
      StructuralMeta<PState> kind = RobotKind.define(kernel, "LinkedRobot", robot.observation());
      robot.start(island, kind, kernel.basicBehavioralMeta(), island.entityOptions());

      assertThatThrownBy(robot::cycle)
          .isInstanceOf(IllegalStateException.class)
          .hasMessageContaining("kernel entity");
      assertThatThrownBy(
              () -> robot.start(island, kind, kernel.basicBehavioralMeta(), island.entityOptions()))
          .isInstanceOf(IllegalStateException.class)
          .hasMessageContaining("already runs");
    } finally {
      runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5));
    }
  }
}

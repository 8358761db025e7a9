package org.armgals.kernel;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import org.armgals.active.Clock;
import org.armgals.active.ManualClock;
import org.armgals.active.ObjectConfig;
import org.junit.jupiter.api.Test;

/**
 * Lock step with a meta in another runtime (paper §2.3: the meta level may live elsewhere): the
 * barriers, the held requests and their release cross the broker, and the base level's run is the
 * same as with a meta of its own runtime.
 */
class LockStepAcrossRuntimesTest extends TwoRuntimesFixture {

  @Test
  void aRemoteMetaInLockStepGivesTheSameRunAsALocalOne() {
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    ReactiveProgramTest.Worker program = new ReactiveProgramTest.Worker();
    Entity robot =
        baseRobots.newEntity(
            "robot",
            baseKernel.basicBehavioralMeta(),
            EntityOptions.defaults()
                .withConfig(ObjectConfig.synchronous(clock))
                .withNotification(NotificationPolicy.statesOnly())
                .withAdaptationPoint(AdaptationPoint.END_OF_CYCLE)
                .withProgram(program)
                .withLockStep(1, WAIT));
    baseTransport.register("robot", robot.address());
    BehavioralMeta meta =
        metaKernel.newBehavioralMeta(
            "meta", ReactiveProgramTest.ecoBelow(new AtomicBoolean()), Damping.none());
    Entity remote = metaKernel.lookupRemote(metaTransport, "robot", metaRobots);
    meta.addBaseLevelEntity(remote).touch();

    // The attachment crosses the broker and is taken at a release: step until the meta knows
    // the robot (the robot works from instant 1 whether it is watched or not).
    assertThat(clock.stepUntil(() -> meta.model(remote).getValue().lastSeq() > 0, 9)).isTrue();
    clock.step(20 - clock.instant());

    List<String> modes = List.copyOf(program.modes);
    assertThat(modes).hasSize(20);
    // Decided on instant 11's state event (battery 0.89), applied at the end of instant 12.
    assertThat(program.firstInstantIn("eco")).isEqualTo(13);
    assertThat(modes)
        .isEqualTo(
            localRun(20)); // the same instants in the same modes as with a meta of its own runtime
    clock.step();
    ModelView model = meta.model(remote).getValue();
    assertThat(model.lockStep()).isTrue();
    assertThat(model.appliedVersion()).isEqualTo(1);
    assertThat(robot.appliedVersion()).isEqualTo(1);
  }

  /** The same robot and policy with the meta in the robot's runtime. */
  private List<String> localRun(int instants) {
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    ReactiveProgramTest.Worker program = new ReactiveProgramTest.Worker();
    BehavioralMeta meta =
        baseKernel.newBehavioralMeta(
            "local-meta", ReactiveProgramTest.ecoBelow(new AtomicBoolean()), Damping.none());
    baseRobots.newEntity(
        "local-robot",
        meta,
        EntityOptions.defaults()
            .withConfig(ObjectConfig.synchronous(clock))
            .withNotification(NotificationPolicy.statesOnly())
            .withAdaptationPoint(AdaptationPoint.END_OF_CYCLE)
            .withProgram(program)
            .withLockStep(1, WAIT));
    clock.step(instants);
    return List.copyOf(program.modes);
  }
}

package org.armgals.kernel;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import org.armgals.active.Clock;
import org.armgals.active.ManualClock;
import org.armgals.active.ObjectConfig;
import org.armgals.kernel.spi.MetaPolicy;
import org.armgals.representation.p.PState;
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
    assertThat(stepUntilKnown(clock, robot, meta, remote)).isTrue();
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

  @Test
  void aRemoteMetaDampsInTheBaseLevelsTimeNotItsOwn() {
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    ReactiveProgramTest.Worker program = new ReactiveProgramTest.Worker();
    Entity robot = lockStepRobot(clock, program);
    // The meta's kernel has a clock of its own that never moves; the base's moves 10 ms an instant.
    Kernel frozen =
        StructuralMeta.bootstrap(
            metaRuntime, new KernelOptions(new ManualTime(), Duration.ofMillis(100), false));
    try {
      StructuralMeta<PState> kind =
          frozen.newStructuralMeta("Robot", KernelFixture.ROBOT, KernelFixture.robotBehaviors());
      BehavioralMeta meta =
          frozen.newBehavioralMeta(
              "meta",
              (context, n) ->
                  context.adapt(n.entity(), new Adaptation.ApplyBehavior("charge", 0.0)),
              new Damping(Duration.ofMillis(25), 100, Duration.ofSeconds(1)));
      Entity remote = frozen.lookupRemote(metaTransport, "robot", kind);
      meta.addBaseLevelEntity(remote).touch();
      assertThat(stepUntilKnown(clock, robot, meta, remote)).isTrue();
      long first = clock.instant();
      for (int i = 0; i < 30; i++) {
        time.advance(Duration.ofMillis(10));
        clock.step();
      }
      clock.step();

      ModelView model = meta.model(remote).getValue();
      // One state event an instant, 10 ms of base time apart: at most one request every 30 ms
      // passes a 25 ms dwell. In the meta's own frozen time, only the first would have.
      long instants = clock.instant() - first;
      assertThat(model.requestedVersion()).isBetween(instants / 3 - 2, instants / 3 + 2);
      assertThat(model.suppressedAdaptations()).isGreaterThan(model.requestedVersion());
      assertThat(robot.appliedVersion()).isGreaterThan(5);
    } finally {
      frozen.close();
    }
  }

  @Test
  void aBaseEntityWhoseMetasRuntimeIsLostStopsWaitingAtOnceAndRunsFree() throws Exception {
    ManualClock clock = Clock.manual(Duration.ofMillis(10));
    ReactiveProgramTest.Worker program = new ReactiveProgramTest.Worker();
    Entity robot =
        baseRobots.newEntity(
            "robot",
            EntityOptions.defaults()
                .withConfig(ObjectConfig.synchronous(clock))
                .withNotification(NotificationPolicy.statesOnly())
                .withAdaptationPoint(AdaptationPoint.END_OF_CYCLE)
                .withProgram(program)
                .withLockStep(1, Duration.ofMinutes(10)));
    baseTransport.register("robot", robot.address());
    BehavioralMeta meta =
        metaKernel.newBehavioralMeta("meta", MetaPolicy.MODEL_ONLY, Damping.none());
    Entity remote = metaKernel.lookupRemote(metaTransport, "robot", metaRobots);
    meta.addBaseLevelEntity(remote).touch();
    assertThat(stepUntilKnown(clock, robot, meta, remote)).isTrue();
    clock.step();
    metaKernel.close(); // the meta stops answering, as if its JVM were killed

    Thread stepper = Thread.ofVirtual().start(() -> clock.step(2)); // waits for the answers
    baseKernel
        .presenceListener()
        .onPresence(new org.armgals.active.spi.PresenceEvent.Lost("meta", Duration.ofSeconds(1)));
    stepper.join(Duration.ofMinutes(1));

    assertThat(stepper.isAlive()).isFalse();
    assertThat(program.modes).hasSize((int) clock.instant());
    assertThat(((EntityImpl<?>) robot).servant.lockStepTimeouts()).isZero();
  }

  private Entity lockStepRobot(ManualClock clock, ReactiveProgramTest.Worker program) {
    Entity robot =
        baseRobots.newEntity(
            "robot",
            EntityOptions.defaults()
                .withConfig(ObjectConfig.synchronous(clock))
                .withNotification(NotificationPolicy.statesOnly())
                .withAdaptationPoint(AdaptationPoint.END_OF_CYCLE)
                .withProgram(program)
                .withLockStep(1, WAIT));
    baseTransport.register("robot", robot.address());
    return robot;
  }

  /**
   * Waits for the remote meta's attachment to arrive at the robot (made with no meta of its own, so
   * that it takes nothing else before), then steps until the meta's model has heard from the robot,
   * at most 9 instants.
   */
  private static boolean stepUntilKnown(
      ManualClock clock, Entity robot, BehavioralMeta meta, Entity remote) {
    awaitQueued(robot);
    return clock.stepUntil(() -> meta.model(remote).getValue().lastSeq() > 0, 9);
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

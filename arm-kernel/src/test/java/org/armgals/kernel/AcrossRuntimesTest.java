package org.armgals.kernel;

import static org.armgals.kernel.BatteryExampleTest.FOLLOW_BATTERY;
import static org.armgals.kernel.BatteryExampleTest.IGNORE_BATTERY;
import static org.armgals.kernel.BatteryExampleTest.LOW_BATTERY;
import static org.armgals.kernel.BatteryExampleTest.THRESHOLDS_ONLY;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.OptionalLong;
import org.armgals.active.Address;
import org.armgals.kernel.spi.MetaPolicy;
import org.armgals.representation.p.PMethod;
import org.armgals.representation.p.PState;
import org.armgals.testkit.BrokerTest;
import org.junit.jupiter.api.Test;

/**
 * The paper's distributed case (§2.3, decision 0024): base entities in one runtime, their
 * behavioral meta in another, both on one embedded Artemis broker, each runtime with its own JMS
 * transport.
 */
class AcrossRuntimesTest extends TwoRuntimesFixture {
  @Test
  void theBatteryExampleRunsWithTheRobotAndItsMetaInDifferentRuntimes() {
    Entity robot = robot("robot", IGNORE_BATTERY);
    Recorder energy = new Recorder(new BatteryExampleTest.Energy());
    BehavioralMeta meta = metaKernel.newBehavioralMeta("energy", energy, Damping.none());
    Entity remote = metaKernel.lookupRemote(metaTransport, "robot", metaRobots);
    assertThat(remote.address()).isEqualTo(robot.address());

    meta.addBaseLevelEntity(remote).touch();
    meta.setFilter(remote, THRESHOLDS_ONLY).touch();
    ModelView attached = awaitModel(meta, remote, v -> v.lastSeq() >= 1);
    assertThat(attached.state()).isEqualTo(robot.state());
    assertThat(robot.behavioralMeta()).as("a meta of another runtime is not seen").isEmpty();
    int seenAtAttachment = energy.seen.size();

    for (int i = 0; i < 3; i++) {
      robot.call("work", 0.2).getValue(); // 0.8, 0.6, 0.4: ignored
    }
    robot.call("work", 0.1).getValue(); // 0.3: inside the band
    robot.call("work", 0.1).getValue(); // 0.2: below the band, the meta starts following
    awaitApplied(robot, 1);
    assertThat(energy.seen).hasSize(seenAtAttachment + 1);
    assertThat(energy.of(ThresholdEvent.class))
        .singleElement()
        .satisfies(t -> assertThat(t.below()).isTrue());
    assertThat(robot.notificationPolicy()).isEqualTo(FOLLOW_BATTERY);
    assertThat(awaitModel(meta, remote, v -> v.appliedVersion() == 1).filter())
        .isEqualTo(LOW_BATTERY);

    robot.call("work", 0.05).getValue(); // 0.15: under 0.2, the meta puts the robot in eco mode
    awaitApplied(robot, 2);
    assertThat(robot.state().observe()).containsEntry("mode", "eco");
    assertThat(energy.of(StateEvent.class).getLast().observation()).containsEntry("battery", 0.15);

    robot.call("charge", 0.5).getValue(); // 0.65: above the band, back to ignoring the battery
    awaitApplied(robot, 4);
    assertThat(robot.state().observe()).containsEntry("mode", "normal");
    assertThat(robot.notificationPolicy()).isEqualTo(IGNORE_BATTERY);
    ModelView model = awaitModel(meta, remote, v -> v.appliedVersion() == 4);
    assertThat(model.filter()).isEqualTo(THRESHOLDS_ONLY);
    assertThat(model.requestedVersion()).isEqualTo(4);
    assertThat(model.resyncRequests()).isZero();
  }

  @Test
  void aModelBuiltFromActionsAcrossRuntimesEqualsTheOneBuiltFromStates() {
    Entity byActions = robot("byActions", NotificationPolicy.actionsOnly());
    Entity byStates = robot("byStates", NotificationPolicy.statesOnly());
    BehavioralMeta meta =
        metaKernel.newBehavioralMeta("models", MetaPolicy.MODEL_ONLY, Damping.none());
    Entity actions = metaKernel.lookupRemote(metaTransport, "byActions", metaRobots);
    Entity states = metaKernel.lookupRemote(metaTransport, "byStates", metaRobots);
    meta.addBaseLevelEntity(actions).touch();
    meta.addBaseLevelEntity(states).touch();
    long snapshot = awaitModel(meta, actions, v -> v.lastSeq() >= 1).lastSeq();
    awaitModel(meta, states, v -> v.lastSeq() >= 1);

    for (Entity r : new Entity[] {byActions, byStates}) {
      r.call("work", 0.3).getValue();
      r.call("eco", null).getValue();
      r.call("charge", 0.15).getValue();
      r.call("work", 0.05).getValue();
    }
    PState expected = (PState) byActions.state();
    assertThat(byStates.state()).isEqualTo(expected);
    assertThat(expected.observe()).containsEntry("battery", 0.8).containsEntry("mode", "eco");

    ModelView fromActions = awaitModel(meta, actions, v -> expected.equals(v.state()));
    ModelView fromStates = awaitModel(meta, states, v -> expected.equals(v.state()));
    assertThat(fromActions.state()).isEqualTo(fromStates.state()).isEqualTo(expected);
    assertThat(fromActions.lastSeq()).as("the snapshot, then four actions").isEqualTo(snapshot + 4);
    assertThat(fromActions.resyncRequests()).isZero();
    assertThat(fromStates.resyncRequests()).isZero();
  }

  @Test
  void aGapMakesTheRemoteMetaAskForAFreshStateAcrossRuntimes() {
    Entity robot = robot("robot", NotificationPolicy.actionsOnly());
    BehavioralMeta meta =
        metaKernel.newBehavioralMeta("models", MetaPolicy.MODEL_ONLY, Damping.none());
    Entity remote = metaKernel.lookupRemote(metaTransport, "robot", metaRobots);
    meta.addBaseLevelEntity(remote).touch();
    awaitModel(meta, remote, v -> v.lastSeq() >= 1);

    ((EntityImpl<?>) robot).object().send(s -> s.loseNotifications(1));
    robot.call("work", 0.5).getValue(); // seq 2: lost in transit
    robot.call("work", 0.1).getValue(); // seq 3: a gap, the meta asks for a state
    PState after = (PState) robot.state();

    ModelView model = awaitModel(meta, remote, v -> !v.resyncing() && v.lastSeq() >= 4);
    assertThat(model.resyncRequests()).isEqualTo(1);
    assertThat(model.state()).isEqualTo(after);
    assertThat(after.observe()).containsEntry("battery", 0.4);
  }

  @BrokerTest(failOnObjectFailures = false) // fails on purpose
  @Test
  void aNotificationThatCannotCrossIsAFailureOfTheEntityAndAGapForTheRemoteMeta() {
    Entity robot = robot("robot", NotificationPolicy.actionsOnly());
    Recorder seen = new Recorder();
    BehavioralMeta meta = metaKernel.newBehavioralMeta("models", seen, Damping.none());
    Entity remote = metaKernel.lookupRemote(metaTransport, "robot", metaRobots);
    meta.addBaseLevelEntity(remote).touch();
    awaitModel(meta, remote, v -> v.lastSeq() >= 1);

    Thread notOnTheWire = new Thread(() -> {});
    assertThatThrownBy(() -> robot.call("eco", notOnTheWire).getValue(WAIT))
        .hasMessageContaining(Thread.class.getName());

    ModelView model =
        awaitModel(meta, remote, v -> !v.resyncing() && robot.state().equals(v.state()));
    assertThat(model.resyncRequests()).isEqualTo(1);
    assertThat(model.state().observe()).containsEntry("mode", "eco");
    assertThat(seen.of(FailureEvent.class))
        .singleElement()
        .satisfies(f -> assertThat(f.toString()).contains(Thread.class.getName()));
  }

  @Test
  void notificationsTheRemoteMetaFiltersOutAreIntegratedNotTakenForGaps() {
    Entity robot = robot("robot", NotificationPolicy.all());
    Recorder seen = new Recorder();
    BehavioralMeta meta = metaKernel.newBehavioralMeta("filtered", seen, Damping.none());
    Entity remote = metaKernel.lookupRemote(metaTransport, "robot", metaRobots);
    meta.addBaseLevelEntity(remote).touch();
    meta.setFilter(remote, "kind = 'action' AND behavior = 'eco'").touch();
    awaitModel(meta, remote, v -> v.lastSeq() >= 1);
    int before = seen.seen.size();

    robot.call("work", 0.1).getValue();
    robot.call("eco", null).getValue();
    robot.call("work", 0.1).getValue();
    PState after = (PState) robot.state();

    ModelView model = awaitModel(meta, remote, v -> after.equals(v.state()) && v.lastSeq() >= 7);
    assertThat(model.resyncRequests()).isZero();
    assertThat(seen.seen.subList(before, seen.seen.size()))
        .singleElement()
        .satisfies(n -> assertThat(((ActionEvent) n).behavior()).isEqualTo("eco"));
  }

  @BrokerTest(failOnObjectFailures = false) // fails on purpose
  @Test
  void adaptationRequestsAcrossRuntimesAreVersionedAndAcknowledged() {
    BehavioralMeta local =
        baseKernel.newBehavioralMeta("local", MetaPolicy.MODEL_ONLY, Damping.none());
    Entity robot =
        baseRobots.newEntity(
            "robot", local, EntityOptions.defaults().withNotification(NotificationPolicy.all()));
    baseTransport.register("robot", robot.address());
    BehavioralMeta meta =
        metaKernel.newBehavioralMeta("adapter", MetaPolicy.MODEL_ONLY, Damping.none());
    Entity remote = metaKernel.lookupRemote(metaTransport, "robot", metaRobots);
    meta.addBaseLevelEntity(remote).touch();
    awaitModel(meta, remote, v -> v.lastSeq() >= 1);
    KernelFixture.drain(local);
    assertThat(local.baseLevelEntities()).as("the previous meta let it go").isEmpty();

    assertThat(meta.adapt(remote, new Adaptation.ApplyBehavior("eco", null)).getValue(WAIT))
        .isEqualTo(OptionalLong.of(1));
    NotificationPolicy modeOnly = NotificationPolicy.statesOnly().observing("mode");
    assertThat(meta.adapt(remote, new Adaptation.SetNotification(modeOnly)).getValue(WAIT))
        .isEqualTo(OptionalLong.of(2));
    awaitApplied(robot, 2);
    ModelView model = awaitModel(meta, remote, v -> v.appliedVersion() == 2);
    assertThat(model.requestedVersion()).isEqualTo(2);
    assertThat(robot.state().observe()).containsEntry("mode", "eco");

    // The handle asks the entity itself, across the broker.
    assertThat(remote.appliedVersion()).isEqualTo(2);
    assertThat(remote.notificationPolicy()).isEqualTo(modeOnly);
    assertThat(remote.call("work", 0.25).getValue(WAIT)).isNull();
    assertThat(remote.state()).isEqualTo(robot.state());
    assertThat(remote.state().observe()).containsEntry("battery", 0.75);
    assertThatThrownBy(() -> remote.call("fly", null).getValue(WAIT)).hasMessageContaining("fly");

    meta.deleteBaseLevelEntity(remote).touch();
    ((EntityImpl<?>) robot)
        .object()
        .callWhen(s -> s.metaAddress() == null, s -> Boolean.TRUE)
        .getValue(WAIT);
    assertThat(meta.baseLevelEntities()).isEmpty();
    assertThatThrownBy(() -> baseKernel.remoteEntity("robot", robot.address(), baseRobots))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("of this runtime");
  }

  @BrokerTest(failOnObjectFailures = false) // fails on purpose
  @Test
  void aBehaviorTaughtByNameReachesTheInstancesOfATwinKindInAnotherRuntime() {
    Entity robot = robot("robot", NotificationPolicy.actionsOnly());
    PMethod turbo = PMethod.of("turbo", (st, in) -> st.with("mode", "turbo"));
    baseRobots.catalog(KernelFixture.ROBOT.methods(turbo)).touch();
    baseTransport.register("Robot", baseRobots.address());
    Address twin = metaTransport.lookup("Robot").getValue(WAIT);
    metaRobots.mirrorTo(twin).touch();
    BehavioralMeta meta =
        metaKernel.newBehavioralMeta("teacher", MetaPolicy.MODEL_ONLY, Damping.none());
    Entity remote = metaKernel.lookupRemote(metaTransport, "robot", metaRobots);
    meta.addBaseLevelEntity(remote).touch();
    awaitModel(meta, remote, v -> v.lastSeq() >= 1);

    metaRobots.addBehavior(turbo).touch(); // flow 4 on arm/SMeta, then flow 5 in the base runtime
    awaitBehavior(robot, "turbo", true);
    assertThat(baseRobots.lookup("turbo")).isPresent();
    assertThat(meta.adapt(remote, new Adaptation.ApplyBehavior("turbo", null)).getValue(WAIT))
        .isEqualTo(OptionalLong.of(1));
    awaitApplied(robot, 1);
    assertThat(robot.state().observe()).containsEntry("mode", "turbo");
    assertThat(awaitModel(meta, remote, v -> robot.state().equals(v.state())).resyncRequests())
        .as("the model replays the new behavior with the meta runtime's copy of the kind")
        .isZero();

    PMethod fly = PMethod.of("fly", (st, in) -> st.with("mode", "flying"));
    metaRobots.addBehavior(fly).touch(); // not in the base kind's catalog: refused there
    metaRobots.deleteBehavior("turbo").touch();
    awaitBehavior(robot, "turbo", false);
    assertThat(baseRobots.lookup("fly")).isEmpty();
    assertThat(baseRobots.behaviors().names()).doesNotContain("fly", "turbo");
    assertThatThrownBy(() -> robot.call("turbo", null).getValue(WAIT))
        .hasMessageContaining("turbo");
  }
}

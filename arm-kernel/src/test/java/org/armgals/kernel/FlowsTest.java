package org.armgals.kernel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.armgals.active.RequestFailedException;
import org.armgals.representation.NoSuchBehaviorException;
import org.armgals.representation.State;
import org.armgals.representation.p.PMethod;
import org.armgals.representation.p.PState;
import org.junit.jupiter.api.Test;

/** The five flows of §3.1, one by one. */
class FlowsTest extends KernelFixture {

  @Test
  void flow1BaseEntityNotifiesItsBehavioralMetaOfActionsAndStatesInSequence() {
    Recorder policy = new Recorder();
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", policy, Damping.none());
    Entity robot = robotKind().newEntity("r1", meta);

    robot.call("work", 0.25).getValue();
    drain(meta);

    assertThat(policy.seen)
        .extracting(Notification::seq)
        .containsExactly(1L, 2L, 3L); // attachment snapshot, then action and state of the step
    assertThat(policy.seen.get(0))
        .isInstanceOfSatisfying(
            StateEvent.class,
            s -> {
              assertThat(s.complete()).isTrue();
              assertThat(s.behavior()).isNull();
            });
    assertThat(policy.seen.get(1))
        .isEqualTo(
            new ActionEvent(robot.address(), meta.address(), 2, time.nanoTime(), "work", 0.25));
    assertThat(policy.seen.get(2))
        .isInstanceOfSatisfying(
            StateEvent.class,
            s -> {
              assertThat(s.behavior()).isEqualTo("work");
              assertThat(s.observation()).containsEntry("battery", 0.75);
            });
  }

  @Test
  void flow2ABehaviorThatReturnsReflectSendsAReflectiveRequestToTheMeta() {
    Recorder policy = new Recorder();
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", policy, Damping.none());
    Entity robot = robotKind().newEntity("r1", meta);

    robot.send("ask", "lost");
    drain(robot);
    drain(meta);

    assertThat(policy.of(ReflectiveRequest.class))
        .singleElement()
        .satisfies(
            r -> {
              assertThat(r.subject()).isEqualTo("lost");
              assertThat(r.entity()).isEqualTo(robot.address());
            });
  }

  @Test
  void flow3AdaptationRequestsAreVersionedAppliedAndAcknowledged() {
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", new Recorder(), Damping.none());
    Entity robot = robotKind().newEntity("r1", meta);

    assertThat(meta.adapt(robot, new Adaptation.ApplyBehavior("eco", null)).getValue()).hasValue(1);
    assertThat(
            meta.adapt(robot, new Adaptation.SetNotification(NotificationPolicy.statesOnly()))
                .getValue())
        .hasValue(2);
    settle(robot, meta, 1);

    assertThat(robot.state().observe()).containsEntry("mode", "eco");
    assertThat(robot.notificationPolicy()).isEqualTo(NotificationPolicy.statesOnly());
    assertThat(robot.appliedVersion()).isEqualTo(2);
    ModelView model = meta.model(robot).getValue();
    assertThat(model.requestedVersion()).isEqualTo(2);
    assertThat(model.appliedVersion()).isEqualTo(2);
    assertThat(model.state()).isEqualTo(robot.state());
  }

  @Test
  void flow3AFailedAdaptationIsAcknowledgedAsNotApplied() {
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", new Recorder(), Damping.none());
    Entity robot = robotKind().newEntity("r1", meta);

    meta.adapt(robot, new Adaptation.ApplyBehavior("fly", null)).getValue();
    settle(robot, meta, 1);

    assertThat(robot.appliedVersion()).isZero();
    assertThat(meta.model(robot).getValue().appliedVersion()).isZero();
  }

  @Test
  void flows4And5TheMetaTeachesTheStructuralMetaWhichHarmonizesEveryInstance() {
    StructuralMeta<PState> kind = robotKind();
    PMethod dance = PMethod.of("dance", (s, in) -> s.with("mode", "dancing"));
    Recorder policy =
        new Recorder(
            (ctx, n) -> {
              if (n instanceof ReflectiveRequest r && r.subject().equals("teach me")) {
                @SuppressWarnings("unchecked")
                StructuralMeta<PState> structural =
                    (StructuralMeta<PState>) ctx.entity(r.entity()).structuralMeta();
                structural.addBehavior(dance); // flow 4
              }
            });
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", policy, Damping.none());
    Entity r1 = kind.newEntity("r1", meta);
    Entity r2 = kind.newEntity("r2", meta);

    r1.call("ask", "teach me").getValue();
    drain(meta);
    drain(kind);

    assertThat(kind.lookup("dance")).containsSame(dance);
    for (Entity r : List.of(r1, r2)) { // flow 5
      assertThat(r.call("dance", null).getValue()).isNull();
      assertThat(r.state().observe()).containsEntry("mode", "dancing");
    }
    drain(meta);
    assertThat(meta.model(r2).getValue().state()).isEqualTo(r2.state());
  }

  @Test
  void aRunningEntityLosesABehaviorItsStructuralMetaDeletes() {
    StructuralMeta<PState> kind = robotKind();
    Recorder policy = new Recorder();
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", policy, Damping.none());
    Entity r1 = kind.newEntity("r1", meta);
    r1.call("eco", null).getValue();

    kind.deleteBehavior("eco").touch();

    assertThat(kind.lookup("eco")).isEmpty();
    assertThatThrownBy(() -> r1.call("eco", null).getValue())
        .isInstanceOf(RequestFailedException.class)
        .hasRootCauseInstanceOf(NoSuchBehaviorException.class);
    assertThatThrownBy(() -> kind.deleteBehavior("eco").touch())
        .hasRootCauseInstanceOf(NoSuchBehaviorException.class);
    drain(kind);
    State state = kernel.basicBehavioralMeta().model(kind).getValue().state();
    List<Object> behaviors = List.copyOf((List<?>) state.observe().get("behaviors"));
    assertThat(behaviors).doesNotContain("eco").contains("work");
  }

  @Test
  void anEntityAddedToAnotherMetaLeavesItsPreviousOneAndADeletedOneHasNoMeta() {
    BehavioralMeta first = kernel.newBehavioralMeta("first", new Recorder(), Damping.none());
    BehavioralMeta second = kernel.newBehavioralMeta("second", new Recorder(), Damping.none());
    Entity robot = robotKind().newEntity("r1", first);

    second.addBaseLevelEntity(robot).touch();
    drain(robot);
    drain(first);
    robot.call("work", 0.5).getValue();
    drain(second);

    assertThat(robot.behavioralMeta()).containsSame(second);
    assertThat(first.baseLevelEntities()).isEmpty();
    assertThat(second.baseLevelEntities()).containsExactly(robot);
    assertThat(second.model(robot).getValue().state()).isEqualTo(robot.state());
    assertThatThrownBy(() -> first.model(robot).getValue())
        .hasRootCauseInstanceOf(IllegalArgumentException.class)
        .hasRootCauseMessage(
            robot.address() + " is not a base entity of first; its base entities are []");

    second.deleteBaseLevelEntity(robot).touch();
    drain(robot);
    assertThat(robot.behavioralMeta()).isEmpty();
    assertThat(robot.call("work", 0.1).getValue()).isNull(); // runs, notifying no one
  }

  @Test
  void aFailureWhileProcessingIsNotifiedToTheBehavioralMeta() {
    Recorder policy = new Recorder();
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", policy, Damping.none());
    Entity robot = robotKind().newEntity("r1", meta);

    assertThatThrownBy(() -> robot.call("explode", 3).getValue())
        .isInstanceOf(RequestFailedException.class)
        .hasRootCauseMessage("boom 3");
    robot.send("explode", 4);
    drain(robot);
    drain(meta);

    assertThat(policy.of(FailureEvent.class))
        .hasSize(2)
        .first()
        .satisfies(
            f -> {
              assertThat(f.error()).isEqualTo(IllegalStateException.class.getName());
              assertThat(f.message()).isEqualTo("boom 3");
            });
    assertThat(robot.state()).isEqualTo(ROBOT.initialState());
    assertThat(meta.model(robot).getValue().resyncing()).isFalse();
  }
}

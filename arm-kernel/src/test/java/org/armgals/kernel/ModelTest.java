package org.armgals.kernel;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.Map;
import org.armgals.representation.State;
import org.armgals.representation.p.PState;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** A behavioral meta's models: built from state or action events, resynchronized after a gap. */
class ModelTest extends KernelFixture {

  static Iterable<Family<?>> families() {
    return Family.all();
  }

  @ParameterizedTest(name = "{0}")
  @MethodSource("families")
  void modelBuiltFromActionEventsEqualsModelBuiltFromStateEvents(Family<?> family) {
    StructuralMeta<?> kind = kind(family);
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", new Recorder(), Damping.none());
    Entity byActions =
        kind.newEntity(
            "byActions",
            meta,
            EntityOptions.defaults().withNotification(NotificationPolicy.actionsOnly()));
    Entity byStates =
        kind.newEntity(
            "byStates",
            meta,
            EntityOptions.defaults().withNotification(NotificationPolicy.statesOnly()));

    for (Map.Entry<String, Object> in : family.inputs()) {
      byActions.send(in.getKey(), in.getValue());
      byStates.send(in.getKey(), in.getValue());
    }
    drain(byActions);
    drain(byStates);

    ModelView fromActions = meta.model(byActions).getValue();
    ModelView fromStates = meta.model(byStates).getValue();
    assertThat(byActions.state()).isEqualTo(byStates.state()).isNotEqualTo(kind.getInitialState());
    assertThat(fromActions.state()).isEqualTo(byActions.state());
    assertThat(fromStates.state()).isEqualTo(byStates.state());
    assertThat(fromActions.resyncing()).isFalse();
    assertThat(fromStates.resyncing()).isFalse();
  }

  private <S extends State> StructuralMeta<S> kind(Family<S> family) {
    return kernel.newStructuralMeta(family.name(), family.space(), family.behaviors());
  }

  @Test
  void aGapInSequenceNumbersMakesTheMetaAskForAFreshState() {
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", new Recorder(), Damping.none());
    Entity robot =
        robotKind()
            .newEntity(
                "r1",
                meta,
                EntityOptions.defaults().withNotification(NotificationPolicy.actionsOnly()));
    robot.call("work", 0.1).getValue();
    ((EntityImpl<?>) robot).object().send(s -> s.loseNotifications(1));
    robot.call("work", 0.2).getValue(); // lost: the model misses it
    robot.call("work", 0.3).getValue(); // seq 4 after 2: a gap
    drain(meta); // it asked for a fresh state
    drain(robot); // which the robot sent

    ModelView model = meta.model(robot).getValue();
    assertThat(model.resyncRequests()).isEqualTo(1);
    assertThat(model.resyncing()).isFalse();
    assertThat(model.state()).isEqualTo(robot.state());
    assertThat(battery(robot)).isEqualTo(0.4);
  }

  @Test
  @SuppressWarnings("unchecked") // a Robot instance is an EntityImpl<PState>
  void resyncIsLevelTriggeredTheModelAsksAgainWhileOutOfSyncAtMostOncePerRetryPeriod() {
    Entity robot = robotKind().newEntity("r1", kernel.basicBehavioralMeta());
    Model<PState> model =
        new Model<>(
            robot,
            ((EntityImpl<PState>) robot).structuralMetaImpl(),
            Damping.none(),
            Duration.ofMillis(100),
            time.nanoTime());
    var a = robot.address();
    var m = kernel.basicBehavioralMeta().address();
    Map<String, Object> full = ROBOT.initialState().observe();

    assertThat(
            model.integrate(
                new StateEvent(a, m, 1, time.nanoTime(), null, full, true), time.nanoTime()))
        .isFalse();
    assertThat(
            model.integrate(
                new ActionEvent(a, m, 3, time.nanoTime(), "work", 0.1), time.nanoTime()))
        .as("a gap asks at once")
        .isTrue();
    assertThat(
            model.integrate(
                new ActionEvent(a, m, 4, time.nanoTime(), "work", 0.1), time.nanoTime()))
        .as("not again within the retry period")
        .isFalse();
    time.advance(Duration.ofMillis(100));
    assertThat(
            model.integrate(
                new ActionEvent(a, m, 5, time.nanoTime(), "work", 0.1), time.nanoTime()))
        .as("still out of sync after the retry period: asks again")
        .isTrue();
    assertThat(model.view(time.nanoTime()).resyncing()).isTrue();
    assertThat(
            model.integrate(
                new StateEvent(
                    a, m, 6, time.nanoTime(), null, Map.of("battery", 0.5, "mode", "eco"), true),
                time.nanoTime()))
        .isFalse();
    time.advance(Duration.ofMillis(500));
    assertThat(
            model.integrate(
                new ActionEvent(a, m, 7, time.nanoTime(), "work", 0.1), time.nanoTime()))
        .isFalse();

    ModelView view = model.view(time.nanoTime());
    assertThat(view.resyncing()).isFalse();
    assertThat(view.resyncRequests()).isEqualTo(2);
    assertThat(view.state()).isEqualTo(new PState(Map.of("battery", 0.4, "mode", "eco")));
  }

  @Test
  void aPartialStateEventKeepsTheValuesItLeavesOut() {
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", new Recorder(), Damping.none());
    Entity robot =
        robotKind()
            .newEntity(
                "r1",
                meta,
                EntityOptions.defaults()
                    .withNotification(NotificationPolicy.statesOnly().observing("battery")));
    robot.call("eco", null).getValue(); // mode is not observed: no state event
    robot.call("work", 0.5).getValue();
    drain(meta);

    assertThat(meta.model(robot).getValue().state())
        .isEqualTo(new PState(Map.of("battery", 0.5, "mode", "normal")));
  }

  @Test
  void aStatechartNotifiedAtACoarseGrainLeavesTheModelWithEveryConsistentLeaf() {
    Family<?> fan = Family.statechart();
    Recorder policy = new Recorder();
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", policy, Damping.none());
    Entity entity =
        kind(fan)
            .newEntity(
                "fan",
                meta,
                EntityOptions.defaults()
                    .withNotification(NotificationPolicy.statesOnly().atDepth(1)));
    entity.send("on", null);
    entity.send("faster", null); // on/slow -> on/fast: the same at depth 1, not notified
    drain(entity);

    ModelView model = meta.model(entity).getValue();
    assertThat(policy.of(StateEvent.class))
        .extracting(StateEvent::complete)
        .containsExactly(true, false); // the attachment snapshot, then "on" at depth 1
    assertThat(model.state()).isNull();
    assertThat(model.candidates()).hasSize(2).contains(entity.state());
  }

  @Test
  void aModelSaysHowStaleItIsByTheKernelsTimeSource() {
    BehavioralMeta meta = kernel.newBehavioralMeta("meta", new Recorder(), Damping.none());
    Entity robot = robotKind().newEntity("r1", meta);
    robot.call("work", 0.1).getValue();
    drain(meta);

    time.advance(Duration.ofSeconds(3));
    assertThat(meta.model(robot).getValue().staleness()).isEqualTo(Duration.ofSeconds(3));

    robot.call("work", 0.1).getValue();
    drain(meta);
    assertThat(meta.model(robot).getValue().staleness()).isZero();
  }
}

package org.armgals.representation;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import org.jspecify.annotations.Nullable;
import org.junit.jupiter.api.Test;

/**
 * The contract of State, StateSpace, Behavior, Behaviors and Activation, run against every family
 * by a subclass that supplies a fixture (docs/architecture.md, convention 9).
 *
 * @param <S> the family's state type
 */
public abstract class RepresentationContract<S extends State> {

  /** A trigger and its input, for a dispatch. */
  public record Trigger(String name, @Nullable Object input) {}

  /** The space of the fixture. */
  protected abstract StateSpace<S> space();

  /** Behaviors of the fixture, at least three. */
  protected abstract Behaviors<S> behaviors();

  /** A behavior applicable in the initial state, leading to another state. */
  protected abstract Trigger applicable();

  /** A behavior of {@link #behaviors()} not applicable in the initial state. */
  protected abstract String inapplicable();

  /** Triggers to dispatch from the initial state, in order; the first takes at least one step. */
  protected abstract List<Trigger> triggers();

  /** A trigger that enables nothing in the initial state. */
  protected abstract String idleTrigger();

  /** A new behavior, not in {@link #behaviors()}, named {@code extra}, applicable initially. */
  protected abstract Behavior<S> extra();

  /** A state that is not in the space. */
  protected abstract S outside();

  /** Part of what {@code state} shows, which may stand for several states. */
  protected abstract Map<String, Object> partialObservation(S state);

  private Activation<S> fresh() {
    return space().activate(space().initialState(), behaviors());
  }

  /** The states the triggers visit, the initial one first. */
  private List<S> visited() {
    Activation<S> a = fresh();
    List<S> states = new ArrayList<>(List.of(a.state()));
    for (Trigger t : triggers()) {
      a.dispatch(t.name(), t.input());
      states.add(a.state());
    }
    return states;
  }

  @Test
  void initialStateIsInTheSpace() {
    assertThat(space().contains(space().initialState())).isTrue();
    assertThat(space().contains(outside())).isFalse();
  }

  @Test
  void withAndWithoutAnswerNewSetsAndLeaveTheOriginalAlone() {
    Behaviors<S> original = behaviors();
    Set<String> before = Set.copyOf(original.names());
    Behaviors<S> more = original.with(extra());
    String first = original.names().iterator().next();
    Behaviors<S> fewer = original.without(first);

    assertThat(original.names()).containsExactlyInAnyOrderElementsOf(before);
    assertThat(more.names()).contains("extra").hasSize(before.size() + 1);
    assertThat(fewer.names()).doesNotContain(first).hasSize(before.size() - 1);
    assertThat(original.lookup("extra")).isEmpty();
    assertThat(original.lookup(first)).isPresent();
  }

  @Test
  void theNamesAndBehaviorsOfASetCannotBeChangedInPlace() {
    Behaviors<S> b = behaviors();
    assertThatThrownBy(() -> b.names().add("x")).isInstanceOf(UnsupportedOperationException.class);
    assertThatThrownBy(() -> b.all().clear()).isInstanceOf(UnsupportedOperationException.class);
  }

  @Test
  void dispatchRefusesANullTrigger() {
    Activation<S> a = fresh();
    assertThatThrownBy(() -> a.dispatch(null, null))
        .isInstanceOf(NullPointerException.class)
        .hasMessageContaining("trigger");
  }

  @Test
  void namesAndAllFollowTheOrderBehaviorsWereAdded() {
    Behaviors<S> b = behaviors().with(extra());
    List<String> names = new ArrayList<>(b.names());
    assertThat(names.get(names.size() - 1)).isEqualTo("extra");
    assertThat(b.all().stream().map(Behavior::name).toList()).isEqualTo(names);
  }

  @Test
  void withReplacesTheBehaviorOfTheSameNameInItsPlace() {
    Behaviors<S> b = behaviors().with(extra());
    List<String> names = new ArrayList<>(b.names());
    Behaviors<S> again = b.with(extra());
    assertThat(new ArrayList<>(again.names())).isEqualTo(names);
    assertThat(again.lookup("extra")).containsSame(extra());
  }

  @Test
  void lookupFindsByNameAndAnswersEmptyForAnUnknownName() {
    for (Behavior<S> behavior : behaviors().all()) {
      assertThat(behaviors().lookup(behavior.name())).containsSame(behavior);
    }
    assertThat(behaviors().lookup("no-such-behavior")).isEmpty();
  }

  @Test
  void withoutAnUnknownNameIsRefusedWithTheName() {
    assertThatThrownBy(() -> behaviors().without("no-such-behavior"))
        .isInstanceOf(NoSuchBehaviorException.class)
        .hasMessageContaining("no-such-behavior")
        .satisfies(
            e -> assertThat(((NoSuchBehaviorException) e).name()).isEqualTo("no-such-behavior"));
  }

  @Test
  void activateStartsInTheGivenStateWithTheGivenBehaviors() {
    Activation<S> a = fresh();
    assertThat(a.state()).isEqualTo(space().initialState());
    assertThat(a.behaviors().names()).containsExactlyElementsOf(behaviors().names());
    assertThat(a.space()).isSameAs(space());
    assertThatThrownBy(() -> space().activate(outside(), behaviors()))
        .isInstanceOf(IllegalArgumentException.class);
  }

  @Test
  void applyMovesToTheStateTheStepLeadsTo() {
    Activation<S> a = fresh();
    S initial = a.state();
    Step<S> step = a.apply(applicable().name(), applicable().input());
    assertThat(step.before()).isEqualTo(initial);
    assertThat(step.after()).isEqualTo(a.state());
    assertThat(step.behavior()).isEqualTo(applicable().name());
    assertThat(step.changed()).isTrue();
    assertThat(space().contains(a.state())).isTrue();
  }

  @Test
  void aBehaviorAppliedDirectlyGivesTheSameStepAsTheActivation() {
    Behavior<S> b = behaviors().lookup(applicable().name()).orElseThrow();
    S initial = space().initialState();
    assertThat(b.isApplicable(initial, applicable().input())).isTrue();
    Step<S> direct = b.apply(initial, applicable().input());
    Step<S> viaActivation = fresh().apply(applicable().name(), applicable().input());
    assertThat(direct.after()).isEqualTo(viaActivation.after());
    assertThat(direct.behavior()).isEqualTo(viaActivation.behavior());
  }

  @Test
  void applyingAnUnknownBehaviorIsRefusedAndKeepsTheState() {
    Activation<S> a = fresh();
    assertThatThrownBy(() -> a.apply("no-such-behavior", null))
        .isInstanceOf(NoSuchBehaviorException.class)
        .hasMessageContaining("no-such-behavior");
    assertThat(a.state()).isEqualTo(space().initialState());
  }

  @Test
  void applyingAnInapplicableBehaviorIsRefusedAndKeepsTheState() {
    Activation<S> a = fresh();
    Behavior<S> b = behaviors().lookup(inapplicable()).orElseThrow();
    assertThat(b.isApplicable(a.state(), null)).isFalse();
    assertThatThrownBy(() -> a.apply(inapplicable(), null))
        .isInstanceOf(BehaviorNotApplicableException.class)
        .hasMessageContaining(inapplicable())
        .satisfies(
            e ->
                assertThat(((BehaviorNotApplicableException) e).behavior())
                    .isEqualTo(inapplicable()));
    assertThatThrownBy(() -> b.apply(a.state(), null))
        .isInstanceOf(BehaviorNotApplicableException.class);
    assertThat(a.state()).isEqualTo(space().initialState());
  }

  @Test
  void dispatchAnswersChainedStepsEndingInTheNewState() {
    Activation<S> a = fresh();
    S start = a.state();
    Trigger first = triggers().get(0);
    List<Step<S>> steps = a.dispatch(first.name(), first.input());
    assertThat(steps).isNotEmpty();
    assertThat(steps.get(0).before()).isEqualTo(start);
    for (int i = 1; i < steps.size(); i++) {
      assertThat(steps.get(i).before()).isEqualTo(steps.get(i - 1).after());
    }
    assertThat(steps.get(steps.size() - 1).after()).isEqualTo(a.state());
    for (Step<S> step : steps) {
      assertThat(a.behaviors().lookup(step.behavior())).isPresent();
    }
  }

  @Test
  void dispatchOfATriggerThatEnablesNothingAnswersNoStepAndKeepsTheState() {
    Activation<S> a = fresh();
    assertThat(a.dispatch(idleTrigger(), null)).isEmpty();
    assertThat(a.state()).isEqualTo(space().initialState());
  }

  @Test
  void harmonizeTeachesANewBehaviorAndKeepsTheState() {
    Activation<S> a = fresh();
    assertThatThrownBy(() -> a.apply("extra", null)).isInstanceOf(NoSuchBehaviorException.class);
    a.harmonize(a.behaviors().with(extra()));
    assertThat(a.state()).isEqualTo(space().initialState());
    Step<S> step = a.apply("extra", null);
    assertThat(step.behavior()).isEqualTo("extra");
  }

  @Test
  void harmonizeCanTakeABehaviorAway() {
    Activation<S> a = fresh();
    a.harmonize(a.behaviors().without(applicable().name()));
    assertThatThrownBy(() -> a.apply(applicable().name(), applicable().input()))
        .isInstanceOf(NoSuchBehaviorException.class);
  }

  @Test
  void resetForcesAStateOfTheSpaceAndRefusesOthers() {
    Activation<S> a = fresh();
    List<S> states = visited();
    S last = states.get(states.size() - 1);
    a.reset(last);
    assertThat(a.state()).isEqualTo(last);
    assertThatThrownBy(() -> a.reset(outside())).isInstanceOf(IllegalArgumentException.class);
    assertThat(a.state()).isEqualTo(last);
  }

  @Test
  void aCompleteObservationMapsBackToItsStateWhateverTheCurrentOne() {
    List<S> states = visited();
    for (S s : states) {
      assertThat(space().contains(s)).isTrue();
      assertThat(space().mapToState(s.observe(), null)).containsExactly(s);
      for (S current : states) {
        assertThat(space().mapToState(s.observe(), current)).containsExactly(s);
      }
    }
  }

  @Test
  void anObservationSurvivesACopyAsAPlainMap() {
    for (S s : visited()) {
      Map<String, Object> copied = new HashMap<>(s.observe());
      assertThat(space().mapToState(copied, null)).containsExactly(s);
    }
  }

  @Test
  void aPartialObservationAnswersCandidatesThatIncludeTheState() {
    for (S s : visited()) {
      Set<S> candidates = space().mapToState(partialObservation(s), s);
      assertThat(candidates).contains(s);
      for (S c : candidates) {
        assertThat(space().contains(c)).isTrue();
      }
    }
  }

  @Test
  void anObservationNamingWhatTheSpaceDoesNotHaveIsRefusedWithTheName() {
    Map<String, Object> observation = new HashMap<>(space().initialState().observe());
    observation.put("noSuchName", "x");
    assertThatThrownBy(() -> space().mapToState(observation, space().initialState()))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("noSuchName");
  }

  @Test
  void replayingTheStepsOnASecondActivationGivesTheSameStates() {
    Activation<S> entity = fresh();
    Activation<S> model = fresh();
    List<S> seen = new ArrayList<>();
    for (Trigger t : triggers()) {
      for (Step<S> step : entity.dispatch(t.name(), t.input())) {
        Step<S> replayed = model.apply(step.behavior(), t.input());
        assertThat(replayed.after()).isEqualTo(step.after());
        assertThat(replayed.result()).isEqualTo(step.result());
        seen.add(step.after());
      }
      assertThat(model.state()).isEqualTo(entity.state());
    }
    assertThat(new LinkedHashSet<>(seen))
        .as("the triggers visit several states")
        .hasSizeGreaterThan(1);
  }

  @Test
  void aLongRandomRunReplaysOnAModelAndEveryStateMapsBackFromItsObservation() {
    Random random = new Random(42);
    Activation<S> entity = fresh();
    Activation<S> model = fresh();
    for (int i = 0; i < 300; i++) {
      Trigger t = triggers().get(random.nextInt(triggers().size()));
      for (Step<S> step : entity.dispatch(t.name(), t.input())) {
        model.apply(step.behavior(), t.input());
      }
      assertThat(model.state()).isEqualTo(entity.state());
      assertThat(space().contains(entity.state())).isTrue();
      assertThat(space().mapToState(entity.state().observe(), null))
          .containsExactly(entity.state());
    }
  }
}

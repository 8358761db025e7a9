package org.armgals.representation.p;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import java.util.Map;
import org.armgals.representation.Activation;
import org.armgals.representation.Step;
import org.junit.jupiter.api.Test;

class ProceduralTest {
  record Robot(int battery, boolean moving, String mode, List<String> log) {}

  private final PSpace space = PSpace.ofRecord(new Robot(100, false, "idle", List.of()));

  @Test
  void aStateIsMadeFromARecordAndTurnsBackIntoOne() {
    Robot robot = new Robot(42, true, "explore", List.of("a", "b"));
    PState state = PState.of(robot);
    assertThat(state.fields()).containsOnlyKeys("battery", "moving", "mode", "log");
    assertThat(state.as(Robot.class)).isEqualTo(robot);
    assertThat(space.contains(state)).isTrue();
    assertThat(space.fields())
        .containsEntry("battery", Integer.class)
        .containsEntry("moving", Boolean.class)
        .containsEntry("log", List.class);
  }

  @Test
  void aDifferentialObservationTakesTheMissingFieldsFromTheCurrentState() {
    PState current = PState.of(new Robot(80, true, "explore", List.of()));
    assertThat(space.mapToState(Map.of("battery", 15), current))
        .containsExactly(PState.of(new Robot(15, true, "explore", List.of())));
  }

  @Test
  void aPartialObservationWithoutACurrentStateIsRefusedNamingTheMissingFields() {
    assertThatThrownBy(() -> space.mapToState(Map.of("battery", 15), null))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("moving")
        .hasMessageContaining("mode");
  }

  @Test
  void anObservedValueOfTheWrongTypeIsRefusedNamingFieldAndType() {
    PState current = space.initialState();
    assertThatThrownBy(() -> space.mapToState(Map.of("battery", "full"), current))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("battery")
        .hasMessageContaining("java.lang.Integer");
  }

  @Test
  void anIntegerFieldAcceptsALongThatCameBackFromAnotherRuntime() {
    PState current = space.initialState();
    assertThat(space.mapToState(Map.of("battery", 7L), current).iterator().next().get("battery"))
        .isEqualTo(7);
  }

  @Test
  void aMethodAnswersItsResultInTheStepAndRespectsItsGuard() {
    PMethod drain =
        PMethod.returning(
                "drain",
                (s, in) -> {
                  int left = (Integer) s.get("battery") - (Integer) in;
                  return new PMethod.Outcome(s.with("battery", left), left);
                })
            .when((s, in) -> in instanceof Integer amount && amount <= (Integer) s.get("battery"));
    Activation<PState> a = space.activate(space.initialState(), space.methods(drain));
    Step<PState> step = a.apply("drain", 30);
    assertThat(step.result()).isEqualTo(70);
    assertThat(a.state().get("battery")).isEqualTo(70);
    assertThat(a.dispatch("drain", 500)).isEmpty();
    assertThat(a.state().get("battery")).isEqualTo(70);
  }

  @Test
  void aMethodLeadingOutOfTheSpaceIsRefusedAndKeepsTheState() {
    PMethod bad = PMethod.of("bad", (s, in) -> new PState(Map.of("other", 1)));
    Activation<PState> a = space.activate(space.initialState(), space.methods(bad));
    assertThatThrownBy(() -> a.apply("bad", null))
        .isInstanceOf(IllegalStateException.class)
        .hasMessageContaining("bad");
    assertThat(a.state()).isEqualTo(space.initialState());
  }

  @Test
  void aStateRefusesUnobservableValuesAndUnknownFields() {
    assertThatThrownBy(() -> new PState(Map.of("when", new Object())))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("when");
    assertThatThrownBy(() -> space.initialState().with("speed", 3))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("speed");
  }

  @Test
  void statesAreValuesWhoseFieldOrderDoesNotMatter() {
    PState a = new PState(Map.of("x", 1, "y", "z"));
    PState b = new PState(new java.util.LinkedHashMap<>(Map.of("y", "z", "x", 1)));
    assertThat(a).isEqualTo(b).hasSameHashCodeAs(b);
  }
}

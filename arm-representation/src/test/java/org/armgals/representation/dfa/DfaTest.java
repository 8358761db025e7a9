package org.armgals.representation.dfa;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Map;
import org.armgals.representation.Activation;
import org.junit.jupiter.api.Test;

class DfaTest {
  private final DfaSpace space = DfaContractTest.SPACE;

  @Test
  void twoTransitionsOnOneLabelFromOneStateAreRefusedNamingBoth() {
    DfaSpace.Builder builder =
        DfaSpace.builder()
            .state("a")
            .state("b")
            .state("c")
            .transition("ab", "a", "x", "b")
            .transition("ac", "a", "x", "c");
    assertThatThrownBy(builder::build)
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'ab'")
        .hasMessageContaining("'ac'")
        .hasMessageContaining("'a'")
        .hasMessageContaining("'x'");
  }

  @Test
  void addingANonDeterministicTransitionAtRunTimeIsRefusedToo() {
    DfaTransition clash = space.transition("clash", "idle", "go", "fast");
    assertThatThrownBy(() -> space.transitions().with(clash))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'start'")
        .hasMessageContaining("'clash'");
  }

  @Test
  void aTransitionToAStateOutsideTheSpaceIsRefusedNamingIt() {
    DfaTransition teleport =
        new DfaTransition("teleport", space.state("idle"), "beam", DfaState.named("nowhere"));
    assertThatThrownBy(() -> space.transitions().with(teleport))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'teleport'")
        .hasMessageContaining("nowhere");
    DfaSpace other = DfaSpace.builder().state("idle").state("elsewhere").build();
    assertThatThrownBy(
            () ->
                space.activate(
                    space.initialState(),
                    space
                        .transitions()
                        .without("start")
                        .with(other.transition("x", "idle", "go", "elsewhere"))))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'x'")
        .hasMessageContaining("another space");
  }

  @Test
  void replacingATransitionByIdIsNotNonDeterminism() {
    DfaTransition rerouted = space.transition("start", "idle", "go", "fast");
    Activation<DfaState> a =
        space.activate(space.initialState(), space.transitions().with(rerouted));
    a.dispatch("go", null);
    assertThat(a.state()).isEqualTo(space.state("fast"));
  }

  @Test
  void theBuilderRefusesUnknownStatesRepeatedNamesAndAnEmptyAutomaton() {
    assertThatThrownBy(() -> DfaSpace.builder().state("a").transition("t", "a", "x", "z").build())
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'z'");
    assertThatThrownBy(() -> DfaSpace.builder().state("a").state("a")).hasMessageContaining("'a'");
    assertThatThrownBy(
            () ->
                DfaSpace.builder()
                    .state("a")
                    .transition("t", "a", "x", "a")
                    .transition("t", "a", "y", "a")
                    .build())
        .hasMessageContaining("'t'");
    assertThatThrownBy(() -> DfaSpace.builder().build()).hasMessageContaining("at least one");
    assertThatThrownBy(() -> DfaSpace.builder().state("a").initial("b").build())
        .hasMessageContaining("'b'");
  }

  @Test
  void anObservationOfASharedOutputAnswersEveryStateThatHasIt() {
    assertThat(space.mapToState(Map.of("moving", true), null))
        .containsExactly(space.state("slow"), space.state("fast"));
    assertThat(space.mapToState(Map.of("moving", true, "speed", 2L), null))
        .containsExactly(space.state("fast"));
    assertThat(space.mapToState(Map.of(), null)).hasSize(4);
    assertThat(space.mapToState(Map.of("state", "idle", "moving", true), null)).isEmpty();
  }

  @Test
  void anObservationOfAnUnknownStateIsRefusedWithItsName() {
    assertThatThrownBy(() -> space.mapToState(Map.of("state", "flying"), null))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("flying");
  }

  @Test
  void dispatchTakesTheTransitionOfThatLabelFromTheCurrentState() {
    Activation<DfaState> a = space.activate(space.state("slow"), space.transitions());
    assertThat(a.dispatch("stop", null))
        .singleElement()
        .extracting(s -> s.behavior())
        .isEqualTo("halt");
    assertThat(a.state()).isEqualTo(space.state("idle"));
  }

  @Test
  void anOutputNamedStateIsRefused() {
    assertThatThrownBy(() -> new DfaState("a", Map.of("state", "x")))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("reserved");
  }
}

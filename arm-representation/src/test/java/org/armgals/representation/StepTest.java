package org.armgals.representation;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Map;
import org.armgals.representation.dfa.DfaState;
import org.junit.jupiter.api.Test;

class StepTest {
  private final DfaState a = DfaState.named("a");
  private final DfaState b = DfaState.named("b");

  @Test
  void aStepChangedTheStateWhenBeforeAndAfterDiffer() {
    assertThat(new Step<>(a, b, "t", null).changed()).isTrue();
    assertThat(new Step<>(a, new DfaState("a", Map.of()), "t", null).changed()).isFalse();
  }

  @Test
  void aStepNeedsBeforeAfterAndBehaviorButNotAResult() {
    assertThatThrownBy(() -> new Step<DfaState>(null, b, "t", null))
        .isInstanceOf(NullPointerException.class)
        .hasMessageContaining("before");
    assertThatThrownBy(() -> new Step<DfaState>(a, null, "t", null)).hasMessageContaining("after");
    assertThatThrownBy(() -> new Step<>(a, b, null, null)).hasMessageContaining("behavior");
    assertThat(new Step<>(a, b, "t", 42).result()).isEqualTo(42);
  }
}

package org.armgals.representation.dfa;

import java.util.List;
import java.util.Map;
import org.armgals.representation.Behavior;
import org.armgals.representation.Behaviors;
import org.armgals.representation.RepresentationContract;
import org.armgals.representation.StateSpace;

class DfaContractTest extends RepresentationContract<DfaState> {
  static final DfaSpace SPACE =
      DfaSpace.builder()
          .state("idle", Map.of("moving", false))
          .state("slow", Map.of("moving", true, "speed", 1))
          .state("fast", Map.of("moving", true, "speed", 2))
          .state("broken")
          .transition("start", "idle", "go", "slow")
          .transition("speedUp", "slow", "faster", "fast")
          .transition("brake", "fast", "stop", "idle")
          .transition("halt", "slow", "stop", "idle")
          .build();

  @Override
  protected StateSpace<DfaState> space() {
    return SPACE;
  }

  @Override
  protected Behaviors<DfaState> behaviors() {
    return SPACE.transitions();
  }

  @Override
  protected Trigger applicable() {
    return new Trigger("start", null);
  }

  @Override
  protected String inapplicable() {
    return "speedUp";
  }

  @Override
  protected List<Trigger> triggers() {
    return List.of(
        new Trigger("go", null),
        new Trigger("faster", null),
        new Trigger("stop", null),
        new Trigger("go", null),
        new Trigger("stop", null));
  }

  @Override
  protected String idleTrigger() {
    return "stop";
  }

  @Override
  protected Behavior<DfaState> extra() {
    return EXTRA;
  }

  private static final DfaTransition EXTRA = SPACE.transition("extra", "idle", "crash", "broken");

  @Override
  protected DfaState outside() {
    return DfaState.named("nowhere");
  }

  @Override
  protected Map<String, Object> partialObservation(DfaState state) {
    return state.outputs().isEmpty() ? Map.of() : Map.of("moving", state.outputs().get("moving"));
  }
}

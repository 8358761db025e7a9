package org.armgals.representation.dfa;

import static java.util.Objects.requireNonNull;

import java.util.List;
import org.armgals.representation.Behaviors;
import org.armgals.representation.Step;
import org.armgals.representation.internal.BaseActivation;
import org.jspecify.annotations.Nullable;

/** An automaton run: a trigger is a label. */
final class DfaActivation extends BaseActivation<DfaState> {

  DfaActivation(DfaSpaceImpl space, DfaState initial, Behaviors<DfaState> behaviors) {
    super(space, initial, behaviors, space.admission());
  }

  /**
   * Takes the transition labelled {@code trigger} from the current state (there is at most one);
   * nothing (an empty list) when there is none.
   */
  @Override
  public List<Step<DfaState>> dispatch(String trigger, @Nullable Object input) {
    requireNonNull(trigger, "trigger");
    for (DfaTransition t : DfaSpaceImpl.transitionsOf(behaviors())) {
      if (t.label().equals(trigger) && t.source().equals(state())) {
        return List.of(apply(t.id(), input));
      }
    }
    return List.of();
  }
}

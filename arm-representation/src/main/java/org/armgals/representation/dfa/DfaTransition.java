package org.armgals.representation.dfa;

import static java.util.Objects.requireNonNull;

import org.armgals.representation.Behavior;
import org.armgals.representation.BehaviorNotApplicableException;
import org.armgals.representation.Step;
import org.jspecify.annotations.Nullable;

/**
 * A labelled transition of an automaton, the behavior of the DFA family. It is applicable exactly
 * in its source state; the input plays no part.
 *
 * @param id the transition's identifier, unique in its behaviors, what an action event carries
 * @param source the state it leaves
 * @param label the trigger it is taken on ({@link org.armgals.representation.Activation#dispatch})
 * @param target the state it leads to
 */
public record DfaTransition(String id, DfaState source, String label, DfaState target)
    implements Behavior<DfaState> {

  /** Checks the components. */
  public DfaTransition {
    requireNonNull(id, "id");
    if (id.isBlank()) {
      throw new IllegalArgumentException("transition id '" + id + "' is blank; expected an id");
    }
    requireNonNull(source, "source");
    requireNonNull(label, "label");
    requireNonNull(target, "target");
  }

  @Override
  public String name() {
    return id;
  }

  @Override
  public boolean isApplicable(DfaState state, @Nullable Object input) {
    return source.equals(requireNonNull(state, "state"));
  }

  @Override
  public Step<DfaState> apply(DfaState state, @Nullable Object input) {
    if (!isApplicable(state, input)) {
      throw new BehaviorNotApplicableException(id, state);
    }
    return new Step<>(state, target, id, null);
  }

  @Override
  public String toString() {
    return id + ": " + source.name() + " -" + label + "-> " + target.name();
  }
}

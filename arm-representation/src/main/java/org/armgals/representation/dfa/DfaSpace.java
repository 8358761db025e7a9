package org.armgals.representation.dfa;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.armgals.representation.Behaviors;
import org.armgals.representation.StateSpace;
import org.jspecify.annotations.Nullable;

/**
 * The states of an automaton, and the transitions it was built with. {@link Behaviors#with} on its
 * behaviors refuses a transition to or from a state outside the space and a second transition on
 * the same label from a state (an error naming both).
 *
 * <p>{@link #mapToState} reads {@code state} (a name) and outputs: an observation giving only
 * outputs answers every state that has them; the current state plays no part.
 *
 * <p>Immutable and thread-safe.
 */
public interface DfaSpace extends StateSpace<DfaState> {

  /** A builder of a space. */
  static Builder builder() {
    return new Builder();
  }

  /**
   * The state named {@code name}.
   *
   * @throws IllegalArgumentException if there is none
   */
  DfaState state(String name);

  /** The states, in the order they were declared. */
  List<DfaState> states();

  /** The transitions the space was built with. */
  Behaviors<DfaState> transitions();

  /**
   * A transition between two states of this space, by their names.
   *
   * @throws IllegalArgumentException if a name is not a state's
   */
  DfaTransition transition(String id, String source, String label, String target);

  /**
   * Builds a {@link DfaSpace}: states (the first is the initial state unless {@link #initial} says
   * otherwise), then transitions between them. Not thread-safe; {@link #build} checks everything.
   */
  final class Builder {
    private final Map<String, DfaState> states = new LinkedHashMap<>();
    private final List<String[]> transitions = new ArrayList<>();
    private @Nullable String initial;

    Builder() {}

    /** Adds a state without outputs. */
    public Builder state(String name) {
      return state(name, Map.of());
    }

    /**
     * Adds a state with outputs.
     *
     * @throws IllegalArgumentException if a state of that name was added already
     */
    public Builder state(String name, Map<String, ?> outputs) {
      DfaState state =
          new DfaState(name, new LinkedHashMap<String, Object>(requireNonNull(outputs, "outputs")));
      if (states.putIfAbsent(name, state) != null) {
        throw new IllegalArgumentException("state '" + name + "' is declared twice");
      }
      return this;
    }

    /** Makes the state named {@code name} the initial one. */
    public Builder initial(String name) {
      this.initial = requireNonNull(name, "name");
      return this;
    }

    /** Adds the transition {@code id} from {@code source} to {@code target} on {@code label}. */
    public Builder transition(String id, String source, String label, String target) {
      transitions.add(
          new String[] {
            requireNonNull(id, "id"),
            requireNonNull(source, "source"),
            requireNonNull(label, "label"),
            requireNonNull(target, "target")
          });
      return this;
    }

    /**
     * The space.
     *
     * @throws IllegalArgumentException if there is no state, the initial state or a transition's
     *     state is not declared, two transitions have the same id, or two transitions leave a state
     *     on the same label
     */
    public DfaSpace build() {
      if (states.isEmpty()) {
        throw new IllegalArgumentException("an automaton needs at least one state; none declared");
      }
      String start = initial != null ? initial : states.keySet().iterator().next();
      return new DfaSpaceImpl(states, start, transitions);
    }
  }
}

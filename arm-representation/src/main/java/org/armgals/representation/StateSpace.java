package org.armgals.representation;

import java.util.Map;
import java.util.Set;
import org.jspecify.annotations.Nullable;

/**
 * The set of possible states of an entity: the product of its fields' types (P), the states of an
 * automaton (DFA), the configurations of a statechart (SC). It knows the initial state, maps
 * observations back to states, and makes activations.
 *
 * <p>Immutable and thread-safe.
 *
 * @param <S> the state type of the family
 */
public interface StateSpace<S extends State> {

  /** The state an entity starts in. */
  S initialState();

  /** Whether {@code state} belongs to this space. */
  boolean contains(S state);

  /**
   * The states an observation may stand for (paper §4.2 {@code mapToState}). A complete observation
   * ({@link State#observe()} of a state) answers that one state. A partial one (some names missing,
   * or a coarse observation such as a composite state of a statechart) answers every state
   * consistent with it; a family that can fill the gaps from {@code current} (P: the fields a
   * differential state event leaves out keep their values) does so. An observation no state matches
   * answers the empty set.
   *
   * @param observation names to values, as {@link State#observe()} gives them
   * @param current the state the observer believed before, if any
   * @throws IllegalArgumentException if the observation names something the space does not have (an
   *     unknown field or state name), with that name in the message
   */
  Set<S> mapToState(Map<String, ?> observation, @Nullable S current);

  /**
   * An activation of an entity in this space (paper §4.2: "an activation for an entity is obtained
   * by calling the method activate defined on the StateSpace of the entity").
   *
   * @throws IllegalArgumentException if {@code initial} is not in this space
   */
  Activation<S> activate(S initial, Behaviors<S> behaviors);
}

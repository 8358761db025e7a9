package org.armgals.representation;

import java.util.List;
import org.jspecify.annotations.Nullable;

/**
 * The behavioral part of a reified representation: the run-time state of one entity and the
 * behaviors it is run with. Made by {@link StateSpace#activate}.
 *
 * <p>Not thread-safe: an activation belongs to one entity and is used only by the thread that runs
 * it (an active object's servant, or a meta-entity's model of a base entity).
 *
 * @param <S> the state type of the family
 */
public interface Activation<S extends State> {

  /** The space this activation lives in. */
  StateSpace<S> space();

  /** The current state. */
  S state();

  /** The behaviors this activation applies. */
  Behaviors<S> behaviors();

  /**
   * Applies the behavior named {@code behavior} to the current state and moves to the state it
   * leads to. This is how an action event is replayed on a model.
   *
   * @throws NoSuchBehaviorException if there is no behavior of that name
   * @throws BehaviorNotApplicableException if it is not applicable in the current state
   */
  Step<S> apply(String behavior, @Nullable Object input);

  /**
   * Reacts to a trigger: P applies the method named {@code trigger}; a DFA takes the transition
   * labelled {@code trigger} from the current state; a statechart runs one run-to-completion step
   * and may take several transitions (one per orthogonal region, plus completion transitions).
   * Answers the steps taken, in order; an empty list when nothing was enabled (the trigger is then
   * discarded, as in UML and SCXML).
   */
  List<Step<S>> dispatch(String trigger, @Nullable Object input);

  /**
   * Replaces the behaviors (the structural meta harmonizes its instances). The current state is
   * kept.
   */
  void harmonize(Behaviors<S> behaviors);

  /**
   * Forces the current state (a model resynchronized from a state event).
   *
   * @throws IllegalArgumentException if {@code state} is not in the space
   */
  void reset(S state);
}

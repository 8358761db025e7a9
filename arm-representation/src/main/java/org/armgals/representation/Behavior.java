package org.armgals.representation;

import org.jspecify.annotations.Nullable;

/**
 * A way for an entity to go from one state to another: a method (P), a transition (DFA, SC).
 *
 * <p>A behavior is a pure function of a state and an input: it does not mutate anything, so that a
 * meta-entity can replay it on its model of an entity (an action event names the behavior, the
 * model applies it to its own copy of the state). Implementations are immutable and thread-safe.
 *
 * @param <S> the state type of the family
 */
public interface Behavior<S extends State> {

  /**
   * The name of this behavior, unique in its {@link Behaviors}: a method name, a transition
   * identifier. It is what an action event carries.
   */
  String name();

  /**
   * Whether this behavior can be applied in {@code state} with {@code input} (its guard; a
   * transition also checks that it leaves from {@code state}).
   */
  boolean isApplicable(S state, @Nullable Object input);

  /**
   * Applies this behavior: the step from {@code state} with {@code input}.
   *
   * @throws BehaviorNotApplicableException if {@link #isApplicable} is false
   */
  Step<S> apply(S state, @Nullable Object input);
}

package org.armgals.representation;

import java.util.Collection;
import java.util.Optional;
import java.util.Set;

/**
 * The set of behaviors an entity can apply, by name: a method dictionary (P), the transitions of an
 * automaton (DFA, SC).
 *
 * <p>Immutable: {@link #with} and {@link #without} answer a new set and leave this one alone, so a
 * structural meta can hand the same set to all its instances and replace it for all of them at once
 * (harmonization) without locking. Iteration order is the order behaviors were added, so that
 * anything derived from it is deterministic.
 *
 * @param <S> the state type of the family
 */
public interface Behaviors<S extends State> {

  /** The behavior of that name, if there is one. */
  Optional<Behavior<S>> lookup(String name);

  /**
   * This set with {@code behavior} added, replacing a behavior of the same name.
   *
   * @throws IllegalArgumentException if the family does not accept that behavior (a DFA transition
   *     naming a state outside the space, for instance)
   */
  Behaviors<S> with(Behavior<S> behavior);

  /**
   * This set without the behavior of that name.
   *
   * @throws NoSuchBehaviorException if there is none
   */
  Behaviors<S> without(String name);

  /** The names, in the order the behaviors were added. */
  Set<String> names();

  /** The behaviors, in the order they were added. */
  Collection<Behavior<S>> all();
}

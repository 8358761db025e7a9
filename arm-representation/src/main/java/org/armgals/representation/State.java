package org.armgals.representation;

import java.util.Map;

/**
 * A possible state of a base-level entity: the values of its fields (P), a state of an automaton
 * (DFA), a configuration of active states (SC).
 *
 * <p>States are immutable values with value equality: two states are the same state when {@code
 * equals} says so, which is what a model compares. {@link #observe()} is what a state event carries
 * about the state, so that a meta-entity in another runtime can rebuild it with {@link
 * StateSpace#mapToState}.
 */
public interface State {

  /**
   * What an observer sees of this state: names to values that are {@code String}, {@code Boolean},
   * a boxed primitive number, or a {@code List} of those (so that they cross runtimes in a
   * message). For every state {@code s} of a space, {@code space.mapToState(s.observe(), null)} is
   * {@code Set.of(s)}.
   */
  Map<String, Object> observe();
}

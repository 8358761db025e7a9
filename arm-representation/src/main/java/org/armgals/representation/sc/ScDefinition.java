package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.Arrays;
import java.util.List;
import org.jspecify.annotations.Nullable;

/**
 * A statechart definition: what an SCXML document says, as a value ({@link Scxml#read} answers one,
 * {@link Scxml#write} takes one). {@link Statechart#of} checks that it holds together.
 *
 * @param name the chart's name
 * @param initial the state entered first; null for the first top-level state
 * @param states the top-level states, in document order
 * @param transitions the transitions, in document order (which is their priority among those of one
 *     source)
 */
public record ScDefinition(
    String name, @Nullable String initial, List<ScNode> states, List<ScTransition> transitions) {

  /** Checks the name and copies the lists. */
  public ScDefinition {
    ScNames.requireName(name, "chart name");
    if (initial != null) {
      ScNames.requireName(initial, "initial state");
    }
    states = List.copyOf(requireNonNull(states, "states"));
    transitions = List.copyOf(requireNonNull(transitions, "transitions"));
  }

  /** A definition of these top-level states, starting in the first, without transitions. */
  public static ScDefinition of(String name, ScNode... states) {
    return new ScDefinition(name, null, Arrays.asList(states), List.of());
  }

  /** This definition with {@code transitions}. */
  public ScDefinition withTransitions(ScTransition... transitions) {
    return new ScDefinition(name, initial, states, Arrays.asList(transitions));
  }

  /** This definition starting in {@code initial}. */
  public ScDefinition withInitial(String initial) {
    return new ScDefinition(name, initial, states, transitions);
  }
}

package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.Arrays;
import java.util.List;

/**
 * A statechart definition: what an SCXML document says, as a value ({@link Scxml#read} answers one,
 * {@link Scxml#write} takes one). {@link Statechart#of} checks that it holds together.
 *
 * @param name the chart's name
 * @param initial the states entered first: one state, or states in different regions of a parallel
 *     state; empty for the first top-level state
 * @param states the top-level states, in document order
 * @param transitions the transitions, in document order (which is their priority among those of one
 *     source)
 */
public record ScDefinition(
    String name, List<String> initial, List<ScNode> states, List<ScTransition> transitions) {

  /** Checks the name and copies the lists. */
  public ScDefinition {
    ScNames.requireName(name, "chart name");
    initial = ScNames.requireNames(initial, "initial state");
    states = List.copyOf(requireNonNull(states, "states"));
    transitions = List.copyOf(requireNonNull(transitions, "transitions"));
  }

  /** A definition of these top-level states, starting in the first, without transitions. */
  public static ScDefinition of(String name, ScNode... states) {
    return new ScDefinition(name, List.of(), Arrays.asList(states), List.of());
  }

  /** This definition with {@code transitions}. */
  public ScDefinition withTransitions(ScTransition... transitions) {
    return new ScDefinition(name, initial, states, Arrays.asList(transitions));
  }

  /** This definition starting in {@code initial} (one state, or states in different regions). */
  public ScDefinition withInitial(String... initial) {
    return new ScDefinition(name, Arrays.asList(initial), states, transitions);
  }
}

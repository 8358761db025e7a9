package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

/**
 * Executable content of a statechart (entry, exit and transition actions). The chart does not run
 * actions: a {@link Run} is named in the step for the entity to run; a {@link Raise} puts an event
 * on the chart's internal queue, taken within the same run-to-completion step.
 */
public sealed interface ScAction {

  /** An action the entity runs, by name ({@code <arm:action name="..."/>} in SCXML). */
  record Run(String name) implements ScAction {
    /** Checks the name. */
    public Run {
      ScNames.requireName(name, "action name");
    }
  }

  /** Raises an internal event ({@code <raise event="..."/>} in SCXML). */
  record Raise(String event) implements ScAction {
    /** Checks the event. */
    public Raise {
      ScNames.requireName(event, "raised event");
    }
  }

  /** A {@link Run} of that name. */
  static ScAction run(String name) {
    return new Run(requireNonNull(name, "name"));
  }

  /** A {@link Raise} of that event. */
  static ScAction raise(String event) {
    return new Raise(requireNonNull(event, "event"));
  }
}

package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import org.jspecify.annotations.Nullable;

/**
 * Executable content of a statechart (entry, exit and transition actions). The chart does not run
 * actions: a {@link Run} is named in the step for the entity to run; a {@link Raise} puts an event
 * on the chart's internal queue, taken within the same run-to-completion step; a {@link Log} is
 * kept in the definition and has no effect.
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

  /**
   * A log message ({@code <log label="..." expr="..."/>} in SCXML), kept so that a document reads
   * and writes as itself, with no effect when the chart runs: the recommendation leaves its output
   * to the platform and forbids it any other effect, and what a chart does is the actions it names
   * for the entity ({@link Run}; decision 0049).
   *
   * @param label the message's label; null for none
   * @param expr its expression, in the condition language (a string literal such as {@code 'pass'},
   *     {@code _event.name}, a field of {@code _event.data}, a condition); null for none
   */
  record Log(@Nullable String label, @Nullable String expr) implements ScAction {
    /**
     * Checks the expression.
     *
     * @throws IllegalArgumentException if {@code expr} is not in the condition language
     */
    public Log {
      if (expr != null) {
        Condition.parse(expr);
      }
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

  /** A {@link Log} of that label and expression (either may be null). */
  static ScAction log(@Nullable String label, @Nullable String expr) {
    return new Log(label, expr);
  }
}

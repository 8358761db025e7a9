package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.jspecify.annotations.Nullable;

/**
 * Executable content of a statechart (entry, exit and transition actions). The chart does not run
 * actions: a {@link Run} is named in the step for the entity to run; a {@link Raise} puts an event
 * on the chart's internal queue, taken within the same run-to-completion step; a {@link Send} puts
 * one on the internal queue or on the chart's external queue, taken after the run-to-completion
 * step within the same dispatch; an {@link If} runs the content of its first branch whose condition
 * holds; a {@link Log} is kept in the definition and has no effect.
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

  /**
   * Sends an event to the chart itself, without delay ({@code <send>} in SCXML, with no {@code
   * target} or {@code target="#_internal"}): to its external queue, taken after the current
   * run-to-completion step, in the same dispatch; or to its internal queue, as a {@link Raise}
   * does. The name is {@code event}, or the value of {@code eventExpr} when the send runs (a
   * string, or a number, boolean, {@code null} or {@code undefined} as ECMAScript writes it; any
   * other value, or a text that is not a name, is an error: the send is dropped, {@code
   * error.execution} goes on the internal queue and the rest of the block is not run).
   *
   * @param event the event's name; null when {@code eventExpr} gives it
   * @param eventExpr an expression of the condition language giving the name; null when {@code
   *     event} does
   * @param internal whether the event goes on the internal queue ({@code #_internal})
   * @param data what the event carries; null for nothing of its own (docs/representations.md says
   *     what {@code _event.data} is then)
   */
  record Send(
      @Nullable String event, @Nullable String eventExpr, boolean internal, @Nullable ScData data)
      implements ScAction {
    /**
     * Checks the event or its expression.
     *
     * @throws IllegalArgumentException unless exactly one of {@code event} (a name) and {@code
     *     eventExpr} (in the condition language) is present
     */
    public Send {
      if ((event == null) == (eventExpr == null)) {
        throw new IllegalArgumentException(
            "send has "
                + (event == null ? "neither event nor eventexpr" : "both event and eventexpr")
                + "; expected exactly one");
      }
      if (event != null) {
        ScNames.requireName(event, "sent event");
      }
      if (eventExpr != null) {
        Condition.parse(eventExpr);
      }
    }

    /** This send, to the internal queue. */
    public Send toInternalQueue() {
      return new Send(event, eventExpr, true, data);
    }

    /** This send, carrying {@code data}. */
    public Send with(ScData data) {
      return new Send(event, eventExpr, internal, requireNonNull(data, "data"));
    }
  }

  /**
   * Conditional content ({@code <if>}, {@code <elseif>}, {@code <else>} in SCXML): runs the actions
   * of the first branch whose condition holds when the content runs, else {@code otherwise}.
   *
   * @param branches the {@code <if>} branch, then each {@code <elseif>}, in order; at least one
   * @param otherwise the {@code <else>} content; empty when there is none
   */
  record If(List<Branch> branches, List<ScAction> otherwise) implements ScAction {
    /**
     * Copies the lists.
     *
     * @throws IllegalArgumentException if there is no branch
     */
    public If {
      branches = List.copyOf(requireNonNull(branches, "branches"));
      otherwise = List.copyOf(requireNonNull(otherwise, "otherwise"));
      if (branches.isEmpty()) {
        throw new IllegalArgumentException("if has no branch; expected at least one condition");
      }
    }

    /** This {@code if} with a further branch ({@code <elseif>}). */
    public If orElseIf(String cond, ScAction... actions) {
      List<Branch> more = new ArrayList<>(branches);
      more.add(new Branch(cond, Arrays.asList(actions)));
      return new If(more, otherwise);
    }

    /** This {@code if} with {@code actions} when no branch's condition holds ({@code <else>}). */
    public If orElse(ScAction... actions) {
      return new If(branches, Arrays.asList(actions));
    }
  }

  /**
   * A condition and the actions it guards, in an {@link If}.
   *
   * @param cond in the condition language (a named {@link Guard} guards transitions only)
   * @param actions run when it holds, in order
   */
  record Branch(String cond, List<ScAction> actions) {
    /**
     * Checks the condition and copies the actions.
     *
     * @throws IllegalArgumentException if the condition is not in the condition language
     */
    public Branch {
      Condition.parse(requireNonNull(cond, "cond"));
      actions = List.copyOf(requireNonNull(actions, "actions"));
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

  /** A {@link Send} of {@code event} to the chart's external queue, without data. */
  static Send send(String event) {
    return new Send(requireNonNull(event, "event"), null, false, null);
  }

  /**
   * A {@link Send} to the chart's external queue, without data, of the event {@code eventExpr}
   * names.
   */
  static Send sendExpr(String eventExpr) {
    return new Send(null, requireNonNull(eventExpr, "eventExpr"), false, null);
  }

  /** An {@link If} of one branch: {@code actions} when {@code cond} holds. */
  static If when(String cond, ScAction... actions) {
    return new If(List.of(new Branch(cond, Arrays.asList(actions))), List.of());
  }
}

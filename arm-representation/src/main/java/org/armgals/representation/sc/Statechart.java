package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.Map;
import org.armgals.representation.Behavior;
import org.armgals.representation.Behaviors;
import org.armgals.representation.StateSpace;
import org.armgals.representation.Step;

/**
 * A statechart as a state space: its states are {@link Configuration}s, its behaviors are its
 * transitions, and {@link org.armgals.representation.Activation#dispatch} runs one
 * run-to-completion step (docs/representations.md says which semantics exactly).
 *
 * <p>{@link #mapToState} reads {@code active} (any ids, coarse or fine: the answer is every legal
 * configuration in which they are all active) and {@code history.<id>} entries; history left out of
 * the observation is taken from the current state, or is empty without one.
 *
 * <p>Immutable and thread-safe, given thread-safe guards.
 */
public interface Statechart extends StateSpace<Configuration> {

  /**
   * The chart of {@code definition}, whose {@code cond}s name guards of {@code guards} or are
   * written in the condition language ({@code In('id')}, {@code true}, comparisons of {@code
   * _event.name} and {@code _event.data} fields: docs/representations.md).
   *
   * @throws IllegalArgumentException if the definition does not hold together (an id used twice, an
   *     initial or target naming no state, initial states or targets that cannot be active
   *     together, a condition that is neither a guard's name nor in the condition language, a start
   *     that does not come to rest), with the culprit named
   */
  static Statechart of(ScDefinition definition, Map<String, Guard> guards) {
    return new StatechartImpl(
        requireNonNull(definition, "definition"), requireNonNull(guards, "guards"));
  }

  /** The chart of {@code definition}, whose conditions are all in the condition language. */
  static Statechart of(ScDefinition definition) {
    return of(definition, Map.of());
  }

  /** The definition the chart was built from. */
  ScDefinition definition();

  /** The definition's transitions, bound to this chart, in document order. */
  Behaviors<Configuration> transitions();

  /**
   * {@code transition} as a behavior of this chart, to add to its behaviors at run time.
   *
   * @throws IllegalArgumentException if its source, a target or its guard is not the chart's
   */
  Behavior<Configuration> bind(ScTransition transition);

  /**
   * The actions the start runs, which the entity runs when it starts: the initial entry's, then
   * those of the eventless transitions and raised or done events it leads to, to completion.
   */
  List<String> initialActions();

  /**
   * A coarse observation of {@code configuration}: the active states no deeper than {@code depth}
   * (top-level states are at depth 1), without history. {@link Configuration#observe()} is the
   * finest.
   *
   * @throws IllegalArgumentException if {@code depth} is below 1, or the configuration is not the
   *     chart's
   */
  Map<String, Object> observe(Configuration configuration, int depth);

  /**
   * Whether {@code step} changed what an observer at {@code depth} sees: an entity that notifies
   * its meta at a coarse grain emits a state event only for such steps.
   *
   * @throws IllegalArgumentException as {@link #observe(Configuration, int)}
   */
  default boolean changedAt(Step<Configuration> step, int depth) {
    return !observe(step.before(), depth).equals(observe(step.after(), depth));
  }

  /** Whether a top-level final state is active: no transition is taken any more. */
  boolean isFinished(Configuration configuration);
}

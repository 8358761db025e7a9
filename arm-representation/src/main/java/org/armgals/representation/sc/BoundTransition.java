package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import org.armgals.representation.Behavior;
import org.armgals.representation.BehaviorNotApplicableException;
import org.armgals.representation.Step;
import org.jspecify.annotations.Nullable;

/**
 * A transition bound to the chart it runs in. Applicable when its source is active, its guard holds
 * and the chart has not finished; the event plays no part (a replay names the transition). The
 * step's result is the list of the actions to run, in order.
 */
final class BoundTransition implements Behavior<Configuration> {
  final StatechartImpl chart;
  final ScTransition spec;

  BoundTransition(StatechartImpl chart, ScTransition spec) {
    this.chart = requireNonNull(chart, "chart");
    this.spec = requireNonNull(spec, "spec");
  }

  @Override
  public String name() {
    return spec.id();
  }

  @Override
  public boolean isApplicable(Configuration state, @Nullable Object input) {
    requireNonNull(state, "state");
    return state.isActive(spec.source())
        && !chart.semantics.finished(state)
        && chart.semantics.guardHolds(spec, state, input);
  }

  @Override
  public Step<Configuration> apply(Configuration state, @Nullable Object input) {
    return step(state, micro(state, input));
  }

  /** The microstep of this transition, raised events included, for a run-to-completion step. */
  Semantics.Micro micro(Configuration state, @Nullable Object input) {
    if (!isApplicable(state, input)) {
      throw new BehaviorNotApplicableException(spec.id(), state);
    }
    return chart.semantics.microstep(spec, state);
  }

  Step<Configuration> step(Configuration before, Semantics.Micro micro) {
    return new Step<>(before, micro.after(), spec.id(), micro.actions());
  }

  @Override
  public String toString() {
    return spec.toString();
  }
}

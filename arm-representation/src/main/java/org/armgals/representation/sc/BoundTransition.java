package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.List;
import org.armgals.representation.Behavior;
import org.armgals.representation.BehaviorNotApplicableException;
import org.armgals.representation.Step;
import org.jspecify.annotations.Nullable;

/**
 * A transition bound to the chart it runs in. Applicable when its source is active, its condition
 * holds and the chart has not finished; the event plays no part (a replay names the transition, and
 * a condition sees no {@code _event.name}). Applying it takes it alone as one microstep; the step's
 * result is the list of the actions to run, in order.
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
        && chart.semantics.holds(spec, state, null, input);
  }

  @Override
  public Step<Configuration> apply(Configuration state, @Nullable Object input) {
    if (!isApplicable(state, input)) {
      throw new BehaviorNotApplicableException(spec.id(), state);
    }
    Semantics.Micro micro = chart.semantics.microstep(List.of(spec), state, null, input, input);
    return new Step<>(state, micro.after(), spec.id(), micro.actions());
  }

  @Override
  public String toString() {
    return spec.toString();
  }
}

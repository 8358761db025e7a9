package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.List;
import org.armgals.representation.Behavior;
import org.armgals.representation.BehaviorNotApplicableException;
import org.armgals.representation.Step;
import org.jspecify.annotations.Nullable;

/**
 * Several transitions of a chart taken together as one microstep, as a dispatch took them: how a
 * model replays a step named by several ids. Applicable when each transition is, in the same
 * configuration, and none conflicts with another.
 */
final class BoundMicrostep implements Behavior<Configuration> {
  private final StatechartImpl chart;
  private final String name;
  private final List<BoundTransition> parts;

  BoundMicrostep(StatechartImpl chart, String name, List<BoundTransition> parts) {
    this.chart = requireNonNull(chart, "chart");
    this.name = requireNonNull(name, "name");
    this.parts = List.copyOf(parts);
  }

  @Override
  public String name() {
    return name;
  }

  @Override
  public boolean isApplicable(Configuration state, @Nullable Object input) {
    requireNonNull(state, "state");
    List<ScTransition> specs = new ArrayList<>();
    for (BoundTransition t : parts) {
      if (!t.isApplicable(state, input) || specs.contains(t.spec)) {
        return false;
      }
      specs.add(t.spec);
    }
    return chart.semantics.withoutConflicts(specs, state).equals(specs);
  }

  @Override
  public Step<Configuration> apply(Configuration state, @Nullable Object input) {
    if (!isApplicable(state, input)) {
      throw new BehaviorNotApplicableException(name, state);
    }
    List<ScTransition> specs = new ArrayList<>();
    for (BoundTransition t : parts) {
      specs.add(t.spec);
    }
    Semantics.Micro micro = chart.semantics.microstep(specs, state, null, input, input);
    return new Step<>(state, micro.after(), name, micro.actions());
  }

  @Override
  public String toString() {
    return name;
  }
}

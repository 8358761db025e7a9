package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.armgals.representation.Behavior;
import org.armgals.representation.Behaviors;
import org.armgals.representation.RepresentationException;
import org.armgals.representation.Step;
import org.armgals.representation.internal.BaseActivation;
import org.jspecify.annotations.Nullable;

/**
 * A statechart run. A dispatch is one run-to-completion step: the eventless transitions the current
 * configuration enables, then the trigger's transitions, then, until nothing is left, eventless
 * transitions and the events raised on the internal queue. Each transition taken is one step.
 */
final class ScActivation extends BaseActivation<Configuration> {
  /** More transitions than this in one run-to-completion step is taken for a loop. */
  static final int MAX_MICROSTEPS = 1_000;

  private final StatechartImpl chart;
  // The behaviors indexed by source and id, rebuilt when harmonize replaces the behaviors.
  private @Nullable Behaviors<Configuration> indexed;
  private Map<String, List<ScTransition>> bySource = Map.of();
  private Map<String, BoundTransition> byId = Map.of();

  ScActivation(StatechartImpl chart, Configuration initial, Behaviors<Configuration> behaviors) {
    super(chart, initial, behaviors, chart.admission());
    this.chart = chart;
  }

  /**
   * Runs one run-to-completion step on {@code trigger}; nothing (an empty list) when the chart has
   * finished. All or nothing: if the step loops, the state is unchanged.
   *
   * @throws RepresentationException if the step takes more than {@value #MAX_MICROSTEPS}
   *     transitions (a loop of eventless transitions or raised events)
   */
  @Override
  public List<Step<Configuration>> dispatch(String trigger, @Nullable Object input) {
    requireNonNull(trigger, "trigger");
    Run run = new Run(input);
    if (chart.semantics.finished(state())) {
      return List.of();
    }
    run.settle();
    run.take(trigger);
    run.settle();
    for (Step<Configuration> step : run.steps) {
      moveTo(step);
    }
    return List.copyOf(run.steps);
  }

  private void index() {
    if (indexed == behaviors()) {
      return;
    }
    Map<String, List<ScTransition>> sources = new LinkedHashMap<>();
    Map<String, BoundTransition> ids = new LinkedHashMap<>();
    for (Behavior<Configuration> b : behaviors().all()) {
      BoundTransition t = (BoundTransition) b;
      sources.computeIfAbsent(t.spec.source(), s -> new ArrayList<>()).add(t.spec);
      ids.put(t.spec.id(), t);
    }
    bySource = sources;
    byId = ids;
    indexed = behaviors();
  }

  /** The bookkeeping of one run-to-completion step. */
  private final class Run {
    final @Nullable Object input;
    final List<Step<Configuration>> steps = new ArrayList<>();
    final Deque<String> internal = new ArrayDeque<>();
    Configuration current = state();

    Run(@Nullable Object input) {
      this.input = input;
      index();
    }

    /** Eventless transitions and internal events until neither is left. */
    void settle() {
      while (true) {
        if (take(null)) {
          continue;
        }
        String event = internal.poll();
        if (event == null) {
          return;
        }
        take(event);
      }
    }

    /** Takes what {@code event} (null: eventless) enables; whether anything was taken. */
    boolean take(@Nullable String event) {
      if (chart.semantics.finished(current)) {
        internal.clear();
        return false;
      }
      boolean taken = false;
      for (ScTransition t : chart.semantics.select(current, event, input, bySource)) {
        BoundTransition bound = byId.get(t.id());
        // A transition taken before may have made a later one of the same microstep inapplicable
        // (a guard on another region): each is checked against the configuration it leaves, so
        // that replaying the steps one by one gives the same result.
        if (bound == null || !bound.isApplicable(current, input)) {
          continue;
        }
        if (steps.size() >= MAX_MICROSTEPS) {
          throw new RepresentationException(
              "a run-to-completion step took more than "
                  + MAX_MICROSTEPS
                  + " transitions, the last "
                  + steps.subList(steps.size() - 3, steps.size()).stream()
                      .map(Step::behavior)
                      .toList()
                  + "; expected eventless transitions and raised events to come to rest");
        }
        Semantics.Micro micro = bound.micro(current, input);
        steps.add(bound.step(current, micro));
        internal.addAll(micro.raised());
        current = micro.after();
        taken = true;
      }
      return taken;
    }
  }
}

package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.armgals.representation.Behavior;
import org.armgals.representation.Behaviors;
import org.armgals.representation.NoSuchBehaviorException;
import org.armgals.representation.RepresentationException;
import org.armgals.representation.Step;
import org.armgals.representation.internal.BaseActivation;
import org.jspecify.annotations.Nullable;

/**
 * A statechart run. A dispatch is the W3C algorithm's main event loop from the trigger until the
 * chart waits for the next external event: the trigger's macrostep (its microstep, then eventless
 * transitions and the events on the internal queue until nothing is left), then one macrostep for
 * each event the chart sent itself, in order. Each microstep is one step, named by the ids of its
 * transitions separated by spaces (one id when it takes one transition), which {@link #apply} takes
 * again as one microstep.
 */
final class ScActivation extends BaseActivation<Configuration> {
  /** More microsteps than this in one run-to-completion step is taken for a loop. */
  static final int MAX_MICROSTEPS = Semantics.MAX_MICROSTEPS;

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
   * Runs the run-to-completion step on {@code trigger}, then those of the events the chart sent
   * itself; nothing (an empty list) when the chart has finished. All or nothing: if the dispatch
   * loops, the state is unchanged.
   *
   * @throws RepresentationException if the dispatch takes more than {@value #MAX_MICROSTEPS}
   *     microsteps (a loop of eventless transitions, raised or sent events)
   */
  @Override
  public List<Step<Configuration>> dispatch(String trigger, @Nullable Object input) {
    requireNonNull(trigger, "trigger");
    if (chart.semantics.finished(state())) {
      return List.of();
    }
    index();
    Semantics.Run run = chart.semantics.new Run(state(), List.of(), List.of(), bySource, input);
    // A configuration the chart reached is stable; one forced by reset, or left unstable by a
    // harmonize that added an eventless transition, comes to rest first.
    run.settle();
    run.external(trigger);
    run.complete();
    List<Step<Configuration>> steps = new ArrayList<>();
    for (Semantics.Taken taken : run.taken()) {
      steps.add(
          new Step<>(taken.before(), taken.micro().after(), taken.name(), taken.micro().actions()));
    }
    for (Step<Configuration> step : steps) {
      moveTo(step);
    }
    return List.copyOf(steps);
  }

  /** A transition's id, or the name of a microstep of several (their ids, space-separated). */
  @Override
  protected Behavior<Configuration> behavior(String name) {
    List<String> ids = List.of(name.strip().split("\\s+"));
    if (ids.size() < 2) {
      return super.behavior(name);
    }
    index();
    List<BoundTransition> parts = new ArrayList<>();
    for (String id : ids) {
      BoundTransition t = byId.get(id);
      if (t == null) {
        throw new NoSuchBehaviorException(name, behaviors().names());
      }
      parts.add(t);
    }
    return new BoundMicrostep(chart, name, parts);
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
}

package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.armgals.representation.Activation;
import org.armgals.representation.Behavior;
import org.armgals.representation.Behaviors;
import org.armgals.representation.RepresentationException;
import org.armgals.representation.internal.OrderedBehaviors;
import org.armgals.representation.sc.Chart.Node;
import org.jspecify.annotations.Nullable;

/** A statechart; see {@link Statechart}. */
final class StatechartImpl implements Statechart {
  private final ScDefinition definition;
  final Semantics semantics;
  private final Configuration initial;
  private final List<String> initialActions;
  private final OrderedBehaviors.Admission<Configuration> admission;
  private final Behaviors<Configuration> transitions;
  private final Configurations configurations;

  StatechartImpl(ScDefinition definition, Map<String, Guard> guards) {
    this.definition = definition;
    this.semantics = new Semantics(new Chart(definition), guards);
    this.configurations = new Configurations(semantics.chart, definition.name());
    this.admission = new Admission(this);
    Behaviors<Configuration> bound = OrderedBehaviors.empty(admission);
    Map<String, List<ScTransition>> bySource = new LinkedHashMap<>();
    for (ScTransition t : definition.transitions()) {
      if (bound.lookup(t.id()).isPresent()) {
        throw new IllegalArgumentException("transition id '" + t.id() + "' is used twice");
      }
      bound = bound.with(bind(t));
      bySource.computeIfAbsent(t.source(), s -> new ArrayList<>()).add(t);
    }
    this.transitions = bound;
    for (Node n : semantics.chart.byId.values()) {
      String where = "state '" + n.id + "'";
      semantics.check(n.onEntry, where);
      semantics.check(n.onExit, where);
      semantics.check(n.defaultActions, where);
      semantics.check(n.doneData, where);
    }
    // The recommendation's start: the initial entry, then eventless transitions and the events it
    // queued (done events included) to completion, then the events it sent itself, with no event
    // and no input.
    Semantics.Micro start = semantics.start();
    List<String> actions = new ArrayList<>(start.actions());
    Configuration at = start.after();
    if (!start.finished()) {
      Semantics.Run run = semantics.new Run(at, start.internal(), start.external(), bySource, null);
      try {
        run.complete();
      } catch (RepresentationException e) {
        throw new IllegalArgumentException(
            "chart '" + definition.name() + "' does not come to rest at start: " + e.getMessage(),
            e);
      }
      for (Semantics.Taken taken : run.taken()) {
        actions.addAll(taken.micro().actions());
      }
      at = run.current();
    }
    this.initial = at;
    this.initialActions = List.copyOf(actions);
  }

  /** Only transitions bound to this chart may join its behaviors. */
  private record Admission(StatechartImpl chart)
      implements OrderedBehaviors.Admission<Configuration> {
    @Override
    public void check(
        Behavior<Configuration> candidate, Collection<Behavior<Configuration>> others) {
      if (!(candidate instanceof BoundTransition t) || t.chart != chart) {
        throw new IllegalArgumentException(
            "behavior '"
                + candidate.name()
                + "' is not a transition of chart '"
                + chart.definition.name()
                + "'; expected one made by its bind(ScTransition)");
      }
    }
  }

  OrderedBehaviors.Admission<Configuration> admission() {
    return admission;
  }

  @Override
  public ScDefinition definition() {
    return definition;
  }

  @Override
  public Behaviors<Configuration> transitions() {
    return transitions;
  }

  @Override
  public Behavior<Configuration> bind(ScTransition transition) {
    semantics.check(requireNonNull(transition, "transition"));
    return new BoundTransition(this, transition);
  }

  @Override
  public List<String> initialActions() {
    return initialActions;
  }

  @Override
  public Configuration initialState() {
    return initial;
  }

  @Override
  public boolean isFinished(Configuration configuration) {
    return semantics.finished(requireNonNull(configuration, "configuration"));
  }

  @Override
  public Map<String, Object> observe(Configuration configuration, int depth) {
    requireNonNull(configuration, "configuration");
    if (depth < 1) {
      throw new IllegalArgumentException("depth " + depth + " is below 1 (the top-level states)");
    }
    if (!contains(configuration)) {
      throw new IllegalArgumentException(
          "configuration " + configuration + " is not one of chart '" + definition.name() + "'");
    }
    List<String> seen = new ArrayList<>();
    for (String id : configuration.active()) {
      if (semantics.chart.byId.get(id).depth <= depth) {
        seen.add(id);
      }
    }
    return Map.of(Configuration.ACTIVE, List.copyOf(seen));
  }

  @Override
  public boolean contains(Configuration configuration) {
    requireNonNull(configuration, "configuration");
    Chart chart = semantics.chart;
    Set<Node> active = new LinkedHashSet<>();
    for (String id : configuration.active()) {
      Node n = chart.byId.get(id);
      if (n == null || n.isHistory()) {
        return false;
      }
      active.add(n);
    }
    if (!Configurations.legal(chart.root, active)) {
      return false;
    }
    if (!configuration.history().keySet().equals(historyIds())) {
      return false;
    }
    for (Map.Entry<String, List<String>> e : configuration.history().entrySet()) {
      if (!remembers(chart.byId.get(e.getKey()), e.getValue())) {
        return false;
      }
    }
    return true;
  }

  private Set<String> historyIds() {
    Set<String> ids = new LinkedHashSet<>();
    for (Node h : semantics.chart.histories) {
      ids.add(h.id);
    }
    return ids;
  }

  private boolean remembers(Node history, Collection<?> ids) {
    Node parent = requireNonNull(history.parent);
    for (Object id : ids) {
      Node n = id instanceof String s ? semantics.chart.byId.get(s) : null;
      if (n == null || n.isHistory() || !n.isDescendantOf(parent)) {
        return false;
      }
    }
    return true;
  }

  @Override
  public Set<Configuration> mapToState(
      Map<String, ?> observation, @Nullable Configuration current) {
    requireNonNull(observation, "observation");
    Chart chart = semantics.chart;
    Set<String> required = new LinkedHashSet<>();
    Map<String, List<String>> history = new LinkedHashMap<>();
    for (String h : historyIds()) {
      history.put(h, List.of());
    }
    if (current != null && contains(current)) {
      history.putAll(current.history());
    }
    for (Map.Entry<String, ?> e : observation.entrySet()) {
      String key = requireNonNull(e.getKey(), "observed name");
      List<String> ids = strings(key, e.getValue());
      if (key.equals(Configuration.ACTIVE)) {
        for (String id : ids) {
          if (chart.node(id, "observed active state").isHistory()) {
            throw new IllegalArgumentException(
                "observed active state '" + id + "' is a history, which is never active");
          }
        }
        required.addAll(ids);
      } else if (key.startsWith(Configuration.HISTORY)
          && history.containsKey(key.substring(Configuration.HISTORY.length()))) {
        String h = key.substring(Configuration.HISTORY.length());
        if (!remembers(chart.byId.get(h), ids)) {
          throw new IllegalArgumentException(
              "observed " + key + " = " + ids + " names states that are not inside its parent");
        }
        history.put(h, ids);
      } else {
        throw new IllegalArgumentException(
            "observation names '"
                + key
                + "'; expected '"
                + Configuration.ACTIVE
                + "' or one of "
                + historyIds().stream().map(h -> Configuration.HISTORY + h).toList());
      }
    }
    Set<Configuration> candidates = new LinkedHashSet<>();
    for (Set<String> config : configurations.all()) {
      if (config.containsAll(required)) {
        candidates.add(new Configuration(config, history));
      }
    }
    return Collections.unmodifiableSet(candidates);
  }

  private static List<String> strings(String key, @Nullable Object value) {
    if (!(value instanceof Collection<?> c)) {
      throw new IllegalArgumentException(
          "observation of '" + key + "' = " + value + "; expected a list of state ids");
    }
    List<String> ids = new ArrayList<>();
    for (Object o : c) {
      if (!(o instanceof String s)) {
        throw new IllegalArgumentException(
            "observation of '" + key + "' holds " + o + "; expected state ids (strings)");
      }
      ids.add(s);
    }
    return ids;
  }

  @Override
  public Activation<Configuration> activate(
      Configuration initial, Behaviors<Configuration> behaviors) {
    return new ScActivation(this, initial, behaviors);
  }

  @Override
  public String toString() {
    return "Statechart[" + definition.name() + "]";
  }
}

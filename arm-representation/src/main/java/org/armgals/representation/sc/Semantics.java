package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;
import org.armgals.representation.RepresentationException;
import org.armgals.representation.sc.Chart.Node;
import org.jspecify.annotations.Nullable;

/**
 * The step semantics of a chart: the algorithm of the W3C SCXML recommendation (appendix D) for the
 * supported subset. A microstep takes a set of transitions at once (all exits, then every
 * transition's content in order, then all entries); a macrostep ({@link Run}) takes eventless
 * transitions and the internal queue's events to completion. Pure: every method answers new values;
 * a {@link Run} is confined to the thread that made it.
 */
final class Semantics {
  /** More microsteps than this in one macrostep is taken for a loop. */
  static final int MAX_MICROSTEPS = 1_000;

  /**
   * What one microstep did: where it led, the actions to run (exits, transition content, entries;
   * then, when it finished the chart, the exits of the states still active), the events it put on
   * the internal queue (raised ones and done events, in order), whether it finished the chart.
   */
  record Micro(Configuration after, List<String> actions, List<String> raised, boolean finished) {}

  final Chart chart;
  private final Map<String, Guard> guards;
  private final Map<String, Condition> conditions = new ConcurrentHashMap<>();

  Semantics(Chart chart, Map<String, Guard> guards) {
    this.chart = chart;
    this.guards = Map.copyOf(guards);
  }

  /** Checks that {@code t} fits the chart: its source, targets and condition exist. */
  void check(ScTransition t) {
    Node source = chart.node(t.source(), "source of transition '" + t.id() + "'");
    if (source.isHistory() || source.isFinal()) {
      throw new IllegalArgumentException(
          "transition '"
              + t.id()
              + "' leaves "
              + source.kind
              + " '"
              + t.source()
              + "'; expected a state or parallel state");
    }
    List<Node> targets = new ArrayList<>();
    for (String target : t.targets()) {
      targets.add(chart.node(target, "target of transition '" + t.id() + "'"));
    }
    Chart.requireTogether(targets, "targets of transition '" + t.id() + "'");
    String cond = t.cond();
    if (cond != null && !guards.containsKey(cond)) {
      Condition c;
      try {
        c = condition(cond);
      } catch (IllegalArgumentException e) {
        throw new IllegalArgumentException(
            "transition '"
                + t.id()
                + "' is guarded by '"
                + cond
                + "', which is not a guard (guards: "
                + guards.keySet()
                + ") nor a condition: "
                + e.getMessage(),
            e);
      }
      for (String id : c.states()) {
        chart.node(id, "In() of transition '" + t.id() + "'");
      }
    }
  }

  private Condition condition(String cond) {
    Condition c = conditions.get(cond);
    if (c == null) {
      c = Condition.parse(cond);
      conditions.put(cond, c);
    }
    return c;
  }

  /**
   * Whether the condition of {@code t} holds in {@code c}, the current event being {@code
   * eventName} (null when unknown: before the first event, or in a replay by name) with the
   * trigger's {@code input} as its data.
   */
  boolean holds(
      ScTransition t, Configuration c, @Nullable String eventName, @Nullable Object input) {
    String cond = t.cond();
    if (cond == null) {
      return true;
    }
    Guard g = guards.get(cond);
    if (g != null) {
      return g.test(c, input);
    }
    return condition(cond).holds(new Condition.Context(c, eventName, input));
  }

  static boolean matches(ScTransition t, @Nullable String event) {
    if (event == null) {
      return t.events().isEmpty();
    }
    for (String d : t.events()) {
      String descriptor = d.endsWith(".*") ? d.substring(0, d.length() - 2) : d;
      if (descriptor.equals("*")
          || event.equals(descriptor)
          || event.startsWith(descriptor + ".")) {
        return true;
      }
    }
    return false;
  }

  /** Whether a top-level final state is active: the chart has finished. */
  boolean finished(Configuration c) {
    for (String id : c.active()) {
      Node n = chart.byId.get(id);
      if (n != null && n.isFinal() && n.parent == chart.root) {
        return true;
      }
    }
    return false;
  }

  /**
   * The optimal enabled transition set of {@code event} (null: the eventless transitions) in {@code
   * c} (selectTransitions and selectEventlessTransitions): for each active atomic state in document
   * order, the first transition of the state or of its nearest ancestor that matches and whose
   * condition holds; then conflicts removed, a transition from a descendant winning. Conditions see
   * {@code eventName}, the current event.
   */
  List<ScTransition> select(
      Configuration c,
      @Nullable String event,
      @Nullable String eventName,
      @Nullable Object input,
      Map<String, List<ScTransition>> bySource) {
    Set<ScTransition> enabled = new LinkedHashSet<>();
    for (Node atomic : chart.nodes(c.active(), "active state")) {
      if (!atomic.isAtomic()) {
        continue;
      }
      List<Node> candidates = new ArrayList<>();
      candidates.add(atomic);
      candidates.addAll(atomic.ancestorsUpTo(chart.root));
      search:
      for (Node s : candidates) {
        for (ScTransition t : bySource.getOrDefault(s.id, List.of())) {
          if (matches(t, event) && holds(t, c, eventName, input)) {
            enabled.add(t);
            break search;
          }
        }
      }
    }
    return withoutConflicts(enabled, c);
  }

  /** removeConflictingTransitions: of two whose exit sets meet, the one from a descendant stays. */
  List<ScTransition> withoutConflicts(Collection<ScTransition> enabled, Configuration c) {
    List<ScTransition> filtered = new ArrayList<>();
    for (ScTransition t1 : enabled) {
      boolean preempted = false;
      List<ScTransition> toRemove = new ArrayList<>();
      Set<Node> exit1 = exitSet(t1, c.active(), c.history());
      for (ScTransition t2 : filtered) {
        Set<Node> both = new LinkedHashSet<>(exit1);
        both.retainAll(exitSet(t2, c.active(), c.history()));
        if (!both.isEmpty()) {
          if (chart.node(t1.source(), "source").isDescendantOf(chart.node(t2.source(), "source"))) {
            toRemove.add(t2);
          } else {
            preempted = true;
            break;
          }
        }
      }
      if (!preempted) {
        filtered.removeAll(toRemove);
        filtered.add(t1);
      }
    }
    return filtered;
  }

  /**
   * Takes the transitions {@code ts} together in {@code c} (microstep): records history and exits
   * the union of their exit sets, innermost first; runs their content in order; enters the union of
   * their entry sets in document order.
   */
  Micro microstep(List<ScTransition> ts, Configuration c) {
    TreeSet<Node> config = chart.nodes(c.active(), "active state");
    Map<String, List<String>> history = new LinkedHashMap<>(c.history());
    List<String> actions = new ArrayList<>();
    List<String> raised = new ArrayList<>();
    TreeSet<Node> exits = new TreeSet<>(Chart.DOCUMENT_ORDER);
    for (ScTransition t : ts) {
      exits.addAll(exitSet(t, c.active(), c.history()));
    }
    List<Node> exitOrder = new ArrayList<>(exits.descendingSet());
    for (Node s : exitOrder) {
      for (Node h : s.historyChildren()) {
        List<Node> remembered = new ArrayList<>();
        for (Node a : config) {
          boolean kept =
              h.kind == ScNode.Kind.DEEP_HISTORY
                  ? a.isAtomic() && a.isDescendantOf(s)
                  : a.parent == s;
          if (kept) {
            remembered.add(a);
          }
        }
        history.put(h.id, Chart.ids(remembered));
      }
    }
    for (Node s : exitOrder) {
      run(s.onExit, actions, raised);
      config.remove(s);
    }
    for (ScTransition t : ts) {
      run(t.actions(), actions, raised);
    }
    Entry toEnter = new Entry(history);
    for (ScTransition t : ts) {
      for (String id : t.targets()) {
        addDescendants(chart.node(id, "target"), toEnter);
      }
      Node domain = domain(t, history);
      if (domain != null) {
        for (Node s : effectiveTargets(t.targets(), history)) {
          addAncestors(s, domain, toEnter);
        }
      }
    }
    boolean finished = enter(toEnter, config, actions, raised);
    return new Micro(configuration(config, history), List.copyOf(actions), raised, finished);
  }

  /** The initial entry: the states entered first, their entry actions and raised events. */
  Micro start() {
    Map<String, List<String>> history = new LinkedHashMap<>();
    for (Node h : chart.histories) {
      history.put(h.id, List.of());
    }
    Entry toEnter = new Entry(history);
    for (Node s : chart.root.initial) {
      addDescendants(s, toEnter);
    }
    for (Node s : chart.root.initial) {
      addAncestors(s, chart.root, toEnter);
    }
    TreeSet<Node> config = new TreeSet<>(Chart.DOCUMENT_ORDER);
    List<String> actions = new ArrayList<>();
    List<String> raised = new ArrayList<>();
    boolean finished = enter(toEnter, config, actions, raised);
    return new Micro(configuration(config, history), List.copyOf(actions), raised, finished);
  }

  /**
   * What a microstep enters (computeEntrySet's statesToEnter, statesForDefaultEntry and
   * defaultHistoryContent), with the history it reads.
   */
  private static final class Entry {
    final TreeSet<Node> states = new TreeSet<>(Chart.DOCUMENT_ORDER);
    final Set<Node> byDefault = new LinkedHashSet<>();
    final Map<Node, List<ScAction>> historyContent = new LinkedHashMap<>();
    final Map<String, List<String>> history;

    Entry(Map<String, List<String>> history) {
      this.history = history;
    }
  }

  /** Enters {@code toEnter} in document order; whether a top-level final state was entered. */
  private boolean enter(
      Entry toEnter, TreeSet<Node> config, List<String> actions, List<String> raised) {
    boolean finished = false;
    for (Node s : toEnter.states) {
      config.add(s);
      run(s.onEntry, actions, raised);
      if (toEnter.byDefault.contains(s)) {
        run(s.defaultActions, actions, raised);
      }
      run(toEnter.historyContent.getOrDefault(s, List.of()), actions, raised);
      if (s.isFinal()) {
        Node parent = requireNonNull(s.parent);
        if (parent == chart.root) {
          finished = true;
        } else {
          raised.add("done.state." + parent.id);
          Node grand = parent.parent;
          if (grand != null && grand.isParallel()) {
            boolean all = true;
            for (Node region : grand.stateChildren()) {
              all &= inFinalState(region, config);
            }
            if (all) {
              raised.add("done.state." + grand.id);
            }
          }
        }
      }
    }
    if (finished) {
      // exitInterpreter: the states still active are exited, innermost first; the configuration
      // keeps them, so that the finished chart shows where it ended.
      for (Node s : config.descendingSet()) {
        run(s.onExit, actions, new ArrayList<>());
      }
    }
    return finished;
  }

  private static boolean inFinalState(Node s, Set<Node> active) {
    if (s.isCompound()) {
      for (Node child : s.stateChildren()) {
        if (child.isFinal() && active.contains(child)) {
          return true;
        }
      }
      return false;
    }
    if (s.isParallel()) {
      for (Node child : s.stateChildren()) {
        if (!inFinalState(child, active)) {
          return false;
        }
      }
      return true;
    }
    return false;
  }

  private static void run(List<ScAction> content, List<String> actions, List<String> raised) {
    for (ScAction a : content) {
      switch (a) {
        case ScAction.Run r -> actions.add(r.name());
        case ScAction.Raise r -> raised.add(r.event());
        case ScAction.Log l -> {
          // No effect: decision 0049.
        }
      }
    }
  }

  private Configuration configuration(Collection<Node> active, Map<String, List<String>> history) {
    return new Configuration(new LinkedHashSet<>(Chart.ids(active)), history);
  }

  /** The active states {@code t} exits (computeExitSet), in document order. */
  private Set<Node> exitSet(
      ScTransition t, Collection<String> active, Map<String, List<String>> history) {
    Set<Node> exits = new LinkedHashSet<>();
    Node domain = domain(t, history);
    if (domain == null) {
      return exits;
    }
    for (Node n : chart.nodes(active, "active state")) {
      if (n.isDescendantOf(domain)) {
        exits.add(n);
      }
    }
    return exits;
  }

  /**
   * The state whose descendants {@code t} exits and enters (getTransitionDomain); null for a
   * targetless transition.
   */
  private @Nullable Node domain(ScTransition t, Map<String, List<String>> history) {
    List<Node> targets = effectiveTargets(t.targets(), history);
    if (targets.isEmpty()) {
      return null;
    }
    Node source = chart.node(t.source(), "source");
    if (t.internal() && source.isCompound()) {
      boolean inside = true;
      for (Node n : targets) {
        inside &= n.isDescendantOf(source);
      }
      if (inside) {
        return source;
      }
    }
    // findLCCA: the least common compound ancestor of the source and the targets.
    for (Node anc : source.ancestorsUpTo(null)) {
      if (anc != chart.root && !anc.isCompound()) {
        continue;
      }
      boolean all = true;
      for (Node n : targets) {
        all &= n.isDescendantOf(anc);
      }
      if (all) {
        return anc;
      }
    }
    return chart.root;
  }

  /** getEffectiveTargetStates: a history stands for what it remembers, or for its default. */
  private List<Node> effectiveTargets(List<String> ids, Map<String, List<String>> history) {
    List<Node> result = new ArrayList<>();
    for (String id : ids) {
      Node n = chart.node(id, "target");
      if (!n.isHistory()) {
        result.add(n);
      } else if (!history.getOrDefault(n.id, List.of()).isEmpty()) {
        result.addAll(chart.nodes(history.get(n.id), "remembered state"));
      } else {
        result.addAll(n.historyDefault);
      }
    }
    return result;
  }

  /** addDescendantStatesToEnter. */
  private void addDescendants(Node s, Entry toEnter) {
    if (s.isHistory()) {
      List<String> remembered = toEnter.history.getOrDefault(s.id, List.of());
      Node parent = requireNonNull(s.parent);
      List<Node> targets;
      if (remembered.isEmpty()) {
        targets = s.historyDefault;
        toEnter.historyContent.put(parent, s.defaultActions);
      } else {
        targets = new ArrayList<>(chart.nodes(remembered, "remembered state"));
      }
      for (Node n : targets) {
        addDescendants(n, toEnter);
      }
      for (Node n : targets) {
        addAncestors(n, parent, toEnter);
      }
      return;
    }
    toEnter.states.add(s);
    if (s.isCompound()) {
      toEnter.byDefault.add(s);
      for (Node n : s.initial) {
        addDescendants(n, toEnter);
      }
      for (Node n : s.initial) {
        addAncestors(n, s, toEnter);
      }
    } else if (s.isParallel()) {
      for (Node child : s.stateChildren()) {
        if (toEnter.states.stream().noneMatch(e -> e.isDescendantOf(child))) {
          addDescendants(child, toEnter);
        }
      }
    }
  }

  /** addAncestorStatesToEnter: the proper ancestors of {@code s} below {@code stop}. */
  private void addAncestors(Node s, Node stop, Entry toEnter) {
    for (Node anc : s.ancestorsUpTo(stop)) {
      if (anc == chart.root) {
        break;
      }
      toEnter.states.add(anc);
      if (anc.isParallel()) {
        for (Node child : anc.stateChildren()) {
          if (toEnter.states.stream().noneMatch(e -> e.isDescendantOf(child))) {
            addDescendants(child, toEnter);
          }
        }
      }
    }
  }

  /** A microstep taken in a macrostep: its transitions, the configuration it left, what it did. */
  record Taken(List<ScTransition> transitions, Configuration before, Micro micro) {
    /** The name of the step: the transitions' ids, separated by spaces. */
    String name() {
      StringBuilder b = new StringBuilder();
      for (ScTransition t : transitions) {
        b.append(b.isEmpty() ? "" : " ").append(t.id());
      }
      return b.toString();
    }
  }

  /**
   * A macrostep in the making (the recommendation's mainEventLoop between two external events): the
   * microsteps taken and the internal queue. Every condition sees the trigger's input as the
   * event's data. Confined to the thread that made it.
   */
  final class Run {
    private final Map<String, List<ScTransition>> bySource;
    private final @Nullable Object input;
    private final List<Taken> taken = new ArrayList<>();
    private final Deque<String> internal = new ArrayDeque<>();
    private Configuration current;
    private @Nullable String event;

    Run(
        Configuration from,
        Collection<String> raised,
        Map<String, List<ScTransition>> bySource,
        @Nullable Object input) {
      this.current = from;
      this.internal.addAll(raised);
      this.bySource = bySource;
      this.input = input;
    }

    /** Where the run is. */
    Configuration current() {
      return current;
    }

    /** The microsteps taken, in order. */
    List<Taken> taken() {
      return taken;
    }

    /** Takes what the external {@code event} enables, if anything. */
    void external(String trigger) {
      if (finished(current)) {
        return;
      }
      event = trigger;
      List<ScTransition> ts = select(current, trigger, trigger, input, bySource);
      if (!ts.isEmpty()) {
        take(ts);
      }
    }

    /**
     * Eventless transitions, else the internal queue's next event, until neither enables anything.
     *
     * @throws RepresentationException after more than {@value #MAX_MICROSTEPS} microsteps
     */
    void settle() {
      while (!finished(current)) {
        List<ScTransition> ts = select(current, null, event, input, bySource);
        if (ts.isEmpty()) {
          String next = internal.poll();
          if (next == null) {
            return;
          }
          event = next;
          ts = select(current, next, next, input, bySource);
        }
        if (!ts.isEmpty()) {
          take(ts);
        }
      }
      internal.clear();
    }

    private void take(List<ScTransition> ts) {
      if (taken.size() >= MAX_MICROSTEPS) {
        throw new RepresentationException(
            "a run-to-completion step took more than "
                + MAX_MICROSTEPS
                + " microsteps, the last "
                + taken.subList(taken.size() - 3, taken.size()).stream().map(Taken::name).toList()
                + "; expected eventless transitions and raised events to come to rest");
      }
      Micro micro = microstep(ts, current);
      taken.add(new Taken(List.copyOf(ts), current, micro));
      internal.addAll(micro.raised());
      current = micro.after();
    }
  }
}

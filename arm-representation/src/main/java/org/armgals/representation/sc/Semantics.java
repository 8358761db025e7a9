package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
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
 * transition's content in order, then all entries); a macrostep takes eventless transitions and the
 * internal queue's events to completion; a {@link Run} takes macrosteps until the external queue
 * holds none of the events the chart sent itself. Pure: every method answers new values; a {@link
 * Run} is confined to the thread that made it.
 */
final class Semantics {
  /** More microsteps than this in one run is taken for a loop. */
  static final int MAX_MICROSTEPS = 1_000;

  /** The event the recommendation puts on the internal queue when executable content fails. */
  static final String ERROR_EXECUTION = "error.execution";

  /**
   * An event on a queue: its name, and its data as conditions see it ({@code _event.data}): what it
   * carries, or the trigger's input when it carries nothing of its own.
   */
  record Event(String name, @Nullable Object data) {}

  /**
   * What one microstep did: where it led, the actions to run (exits, transition content, entries;
   * then, when it finished the chart, the exits of the states still active), the events it put on
   * the internal queue (raised and sent ones, done events, errors, in order) and on the external
   * queue (sent ones), whether it finished the chart.
   */
  record Micro(
      Configuration after,
      List<String> actions,
      List<Event> internal,
      List<Event> external,
      boolean finished) {}

  final Chart chart;
  private final Map<String, Guard> guards;
  private final Map<String, Condition> conditions = new ConcurrentHashMap<>();

  Semantics(Chart chart, Map<String, Guard> guards) {
    this.chart = chart;
    this.guards = Map.copyOf(guards);
  }

  /**
   * Checks that {@code t} fits the chart: its source, targets and condition exist, and the states
   * its content's expressions name.
   */
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
    check(t.actions(), "transition '" + t.id() + "'");
  }

  /** Checks that the expressions of {@code content} name states of the chart in their In(). */
  void check(List<ScAction> content, String where) {
    for (ScAction a : content) {
      switch (a) {
        case ScAction.Run r -> {}
        case ScAction.Raise r -> {}
        case ScAction.Log l -> checkExpr(l.expr(), where);
        case ScAction.Send send -> {
          checkExpr(send.eventExpr(), where);
          check(send.data(), where);
        }
        case ScAction.If i -> {
          for (ScAction.Branch b : i.branches()) {
            checkExpr(b.cond(), where);
            check(b.actions(), where);
          }
          check(i.otherwise(), where);
        }
      }
    }
  }

  /** Checks that the expressions of {@code data} name states of the chart in their In(). */
  void check(@Nullable ScData data, String where) {
    switch (data) {
      case null -> {}
      case ScData.Params p -> {
        for (ScData.Param param : p.params()) {
          checkExpr(param.expr(), where);
        }
      }
      case ScData.Text t -> {}
      case ScData.Expr e -> checkExpr(e.expr(), where);
    }
  }

  private void checkExpr(@Nullable String expr, String where) {
    if (expr != null) {
      for (String id : condition(expr).states()) {
        chart.node(id, "In() in the content of " + where);
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
   * eventName} (null when unknown: before the first event, or in a replay by name) with {@code
   * data} as its data. A named guard sees {@code data} as its input.
   */
  boolean holds(
      ScTransition t, Configuration c, @Nullable String eventName, @Nullable Object data) {
    String cond = t.cond();
    if (cond == null) {
      return true;
    }
    Guard g = guards.get(cond);
    if (g != null) {
      return g.test(c, data);
    }
    return condition(cond).holds(new Condition.Context(c::isActive, eventName, data));
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
   * {@code eventName} and {@code data}, the current event's.
   */
  List<ScTransition> select(
      Configuration c,
      @Nullable String event,
      @Nullable String eventName,
      @Nullable Object data,
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
          if (matches(t, event) && holds(t, c, eventName, data)) {
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
   * their entry sets in document order. The content sees {@code eventName} and {@code eventData} as
   * the current event's; {@code input}, the trigger's input, is the data of the events it raises or
   * sends without data of their own.
   */
  Micro microstep(
      List<ScTransition> ts,
      Configuration c,
      @Nullable String eventName,
      @Nullable Object eventData,
      @Nullable Object input) {
    TreeSet<Node> config = chart.nodes(c.active(), "active state");
    Map<String, List<String>> history = new LinkedHashMap<>(c.history());
    Exec x = new Exec(config, eventName, eventData, input);
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
      x.block(s.onExit);
      config.remove(s);
    }
    for (ScTransition t : ts) {
      x.block(t.actions());
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
    boolean finished = enter(toEnter, x);
    return x.micro(configuration(config, history), finished);
  }

  /** The initial entry: the states entered first, their entry actions and the events they queue. */
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
    Exec x = new Exec(config, null, null, null);
    boolean finished = enter(toEnter, x);
    return x.micro(configuration(config, history), finished);
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

  /**
   * Enters {@code toEnter} in document order, running the content with {@code x}; whether a
   * top-level final state was entered.
   */
  private boolean enter(Entry toEnter, Exec x) {
    boolean finished = false;
    for (Node s : toEnter.states) {
      x.config.add(s);
      x.block(s.onEntry);
      if (toEnter.byDefault.contains(s)) {
        x.block(s.defaultActions);
      }
      x.block(toEnter.historyContent.getOrDefault(s, List.of()));
      if (s.isFinal()) {
        Node parent = requireNonNull(s.parent);
        if (parent == chart.root) {
          // Its done data would go with done.invoke to an invoking session, which there is not.
          finished = true;
        } else {
          x.done(parent, s.doneData);
          Node grand = parent.parent;
          if (grand != null && grand.isParallel()) {
            boolean all = true;
            for (Node region : grand.stateChildren()) {
              all &= inFinalState(region, x.config);
            }
            if (all) {
              x.done(grand, null);
            }
          }
        }
      }
    }
    if (finished) {
      // exitInterpreter: the states still active are exited, innermost first, and what their
      // content queues is dropped; the configuration keeps them, so that the finished chart shows
      // where it ended.
      Exec end = new Exec(new TreeSet<>(x.config), x.eventName, x.eventData, x.input);
      for (Node s : x.config.descendingSet()) {
        end.block(s.onExit);
        end.config.remove(s);
      }
      x.actions.addAll(end.actions);
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

  /**
   * Executable content as a microstep runs it: the configuration it sees (which changes as states
   * are exited and entered), the event being processed, and what the content does.
   */
  private final class Exec {
    final TreeSet<Node> config;
    final @Nullable String eventName;
    final @Nullable Object eventData;
    final @Nullable Object input;
    final List<String> actions = new ArrayList<>();
    final List<Event> internal = new ArrayList<>();
    final List<Event> external = new ArrayList<>();

    Exec(
        TreeSet<Node> config,
        @Nullable String eventName,
        @Nullable Object eventData,
        @Nullable Object input) {
      this.config = config;
      this.eventName = eventName;
      this.eventData = eventData;
      this.input = input;
    }

    Micro micro(Configuration after, boolean finished) {
      return new Micro(
          after, List.copyOf(actions), List.copyOf(internal), List.copyOf(external), finished);
    }

    private Condition.Context context() {
      return new Condition.Context(
          id -> {
            Node n = chart.byId.get(id);
            return n != null && config.contains(n);
          },
          eventName,
          eventData);
    }

    /** Runs a block (an onentry, an onexit, a transition's content); an error ends it. */
    void block(List<ScAction> content) {
      run(content);
    }

    /** done.state.{@code state}, with {@code data} evaluated now. */
    void done(Node state, @Nullable ScData data) {
      internal.add(new Event("done.state." + state.id, data == null ? input : data(data)));
    }

    /** Runs {@code content} in order; false when an error stopped it (W3C 4.9). */
    private boolean run(List<ScAction> content) {
      for (ScAction a : content) {
        boolean ok =
            switch (a) {
              case ScAction.Run r -> actions.add(r.name());
              case ScAction.Raise r -> internal.add(new Event(r.event(), input));
              case ScAction.Log l -> true; // No effect: decision 0049.
              case ScAction.Send send -> send(send);
              case ScAction.If i -> branch(i);
            };
        if (!ok) {
          return false;
        }
      }
      return true;
    }

    private boolean branch(ScAction.If i) {
      for (ScAction.Branch b : i.branches()) {
        if (condition(b.cond()).holds(context())) {
          return run(b.actions());
        }
      }
      return run(i.otherwise());
    }

    /** Queues the event {@code send} names; an error when its expression names none. */
    private boolean send(ScAction.Send send) {
      String name = send.event();
      if (name == null) {
        name = Condition.text(condition(requireNonNull(send.eventExpr())).value(context()));
        if (name == null || name.isEmpty() || name.chars().anyMatch(Character::isWhitespace)) {
          internal.add(new Event(ERROR_EXECUTION, input));
          return false;
        }
      }
      ScData data = send.data();
      Event event = new Event(name, data == null ? input : data(data));
      return send.internal() ? internal.add(event) : external.add(event);
    }

    /** The value of {@code data} now: a map of the params' values, or the content's value. */
    private @Nullable Object data(ScData data) {
      return switch (data) {
        case ScData.Params p -> {
          Map<String, @Nullable Object> values = new LinkedHashMap<>();
          for (ScData.Param param : p.params()) {
            values.put(param.name(), condition(param.expr()).value(context()));
          }
          yield Collections.unmodifiableMap(values);
        }
        case ScData.Text t -> ContentText.value(t.text());
        case ScData.Expr e -> condition(e.expr()).value(context());
      };
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
   * The recommendation's mainEventLoop from one external event until the chart waits for the next:
   * the microsteps taken, the internal queue, and the external queue of the events the chart sent
   * itself. Conditions see the data of the event being processed (for eventless transitions, of the
   * last one); an event that carries none of its own has the trigger's input. Confined to the
   * thread that made it.
   */
  final class Run {
    private final Map<String, List<ScTransition>> bySource;
    private final @Nullable Object input;
    private final List<Taken> taken = new ArrayList<>();
    private final Deque<Event> internal = new ArrayDeque<>();
    private final Deque<Event> external = new ArrayDeque<>();
    private Configuration current;
    private @Nullable Event event;

    /**
     * A run from {@code from}, with {@code internal} and {@code external} queued (by the start),
     * {@code input} being the trigger's input.
     */
    Run(
        Configuration from,
        Collection<Event> internal,
        Collection<Event> external,
        Map<String, List<ScTransition>> bySource,
        @Nullable Object input) {
      this.current = from;
      this.internal.addAll(internal);
      this.external.addAll(external);
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

    /** Takes what the external {@code trigger}, with the run's input as its data, enables. */
    void external(String trigger) {
      take(new Event(trigger, input));
    }

    /**
     * Macrosteps until the chart waits: eventless transitions and the internal queue's events to
     * completion, then the next event the chart sent itself, until none is left.
     *
     * @throws RepresentationException after more than {@value #MAX_MICROSTEPS} microsteps
     */
    void complete() {
      settle();
      for (Event next = external.poll(); next != null; next = external.poll()) {
        take(next);
        settle();
      }
    }

    private void take(Event e) {
      if (finished(current)) {
        external.clear();
        return;
      }
      event = e;
      List<ScTransition> ts = select(current, e.name(), e.name(), e.data(), bySource);
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
        Event last = event;
        List<ScTransition> ts =
            select(
                current,
                null,
                last == null ? null : last.name(),
                last == null ? input : last.data(),
                bySource);
        if (ts.isEmpty()) {
          Event next = internal.poll();
          if (next == null) {
            return;
          }
          event = next;
          ts = select(current, next.name(), next.name(), next.data(), bySource);
        }
        if (!ts.isEmpty()) {
          take(ts);
        }
      }
      internal.clear();
      external.clear();
    }

    private void take(List<ScTransition> ts) {
      if (taken.size() >= MAX_MICROSTEPS) {
        throw new RepresentationException(
            "a dispatch took more than "
                + MAX_MICROSTEPS
                + " microsteps, the last "
                + taken.subList(taken.size() - 3, taken.size()).stream().map(Taken::name).toList()
                + "; expected eventless transitions and raised or sent events to come to rest");
      }
      Event e = event;
      Micro micro =
          microstep(ts, current, e == null ? null : e.name(), e == null ? input : e.data(), input);
      taken.add(new Taken(List.copyOf(ts), current, micro));
      internal.addAll(micro.internal());
      external.addAll(micro.external());
      current = micro.after();
    }
  }
}

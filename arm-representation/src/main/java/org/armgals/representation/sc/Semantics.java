package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.armgals.representation.sc.Chart.Node;
import org.jspecify.annotations.Nullable;

/**
 * The step semantics of a chart, after the algorithm of the W3C SCXML recommendation (appendix D):
 * transition selection with priority to descendants, conflict removal, exit and entry sets with
 * history, done events. Pure: every method answers new values.
 */
final class Semantics {
  private static final Pattern IN = Pattern.compile("In\\(\\s*'?([^'()\\s]+)'?\\s*\\)");

  /** What one transition did: where it led, the actions to run, the events it raised. */
  record Micro(Configuration after, List<String> actions, List<String> raised) {}

  final Chart chart;
  private final Map<String, Guard> guards;

  Semantics(Chart chart, Map<String, Guard> guards) {
    this.chart = chart;
    this.guards = Map.copyOf(guards);
  }

  /** Checks that {@code t} fits the chart: its source, targets and guard exist. */
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
    for (String target : t.targets()) {
      chart.node(target, "target of transition '" + t.id() + "'");
    }
    String cond = t.cond();
    if (cond != null) {
      Matcher in = IN.matcher(cond);
      if (in.matches()) {
        chart.node(in.group(1), "In() of transition '" + t.id() + "'");
      } else if (!guards.containsKey(cond)) {
        throw new IllegalArgumentException(
            "transition '"
                + t.id()
                + "' is guarded by '"
                + cond
                + "', which is not a guard; guards: "
                + guards.keySet()
                + " or In(stateId)");
      }
    }
  }

  boolean guardHolds(ScTransition t, Configuration c, @Nullable Object input) {
    String cond = t.cond();
    if (cond == null) {
      return true;
    }
    Matcher in = IN.matcher(cond);
    if (in.matches()) {
      return c.isActive(in.group(1));
    }
    return requireNonNull(guards.get(cond), cond).test(c, input);
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
   * The transitions {@code event} (null: eventless) enables in {@code c}, in the order they are
   * taken: for each active atomic state in document order, the first enabled transition of the
   * state or its nearest ancestor; then conflicts removed, a transition from a descendant winning.
   */
  List<ScTransition> select(
      Configuration c,
      @Nullable String event,
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
          if (matches(t, event) && guardHolds(t, c, input)) {
            enabled.add(t);
            break search;
          }
        }
      }
    }
    return withoutConflicts(enabled, c);
  }

  private List<ScTransition> withoutConflicts(Collection<ScTransition> enabled, Configuration c) {
    List<ScTransition> filtered = new ArrayList<>();
    for (ScTransition t1 : enabled) {
      boolean preempted = false;
      List<ScTransition> toRemove = new ArrayList<>();
      Set<Node> exit1 = exitSet(t1, c);
      for (ScTransition t2 : filtered) {
        Set<Node> both = new LinkedHashSet<>(exit1);
        both.retainAll(exitSet(t2, c));
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

  /** Takes {@code t} in {@code c}: exits, the transition's actions, entries. */
  Micro microstep(ScTransition t, Configuration c) {
    TreeSet<Node> active = chart.nodes(c.active(), "active state");
    Map<String, List<String>> history = new LinkedHashMap<>(c.history());
    List<String> actions = new ArrayList<>();
    List<String> raised = new ArrayList<>();
    Node domain = t.targets().isEmpty() ? null : domain(t, c);
    if (domain != null) {
      List<Node> exits = new ArrayList<>(active.descendingSet());
      exits.removeIf(n -> !n.isDescendantOf(domain));
      for (Node s : exits) {
        for (Node h : s.historyChildren()) {
          List<Node> remembered = new ArrayList<>();
          for (Node a : active) {
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
      for (Node s : exits) {
        run(s.onExit, actions, raised);
        active.remove(s);
      }
    }
    run(t.actions(), actions, raised);
    if (domain != null) {
      TreeSet<Node> toEnter = new TreeSet<>(Chart.DOCUMENT_ORDER);
      for (String id : t.targets()) {
        addDescendants(chart.node(id, "target"), toEnter, history);
      }
      for (Node s : effectiveTargets(t.targets(), history)) {
        addAncestors(s, domain, toEnter, history);
      }
      enter(toEnter, active, actions, raised);
    }
    return new Micro(configuration(active, history), List.copyOf(actions), List.copyOf(raised));
  }

  /** The initial configuration, and the entry actions that entering it runs. */
  Micro initial() {
    TreeSet<Node> toEnter = new TreeSet<>(Chart.DOCUMENT_ORDER);
    Map<String, List<String>> history = new LinkedHashMap<>();
    for (Node h : chart.histories) {
      history.put(h.id, List.of());
    }
    for (Node s : chart.root.initial) {
      addDescendants(s, toEnter, history);
      addAncestors(s, chart.root, toEnter, history);
    }
    TreeSet<Node> active = new TreeSet<>(Chart.DOCUMENT_ORDER);
    List<String> actions = new ArrayList<>();
    // Done events of the initial entry are not raised: the initial configuration is taken as
    // stable (docs/representations.md).
    enter(toEnter, active, actions, new ArrayList<>());
    return new Micro(configuration(active, history), List.copyOf(actions), List.of());
  }

  private void enter(
      TreeSet<Node> toEnter, TreeSet<Node> active, List<String> actions, List<String> raised) {
    for (Node s : toEnter) {
      active.add(s);
      run(s.onEntry, actions, raised);
      if (s.isFinal()) {
        Node parent = requireNonNull(s.parent);
        if (parent != chart.root) {
          raised.add("done.state." + parent.id);
          Node grand = parent.parent;
          if (grand != null && grand.isParallel()) {
            boolean all = true;
            for (Node region : grand.stateChildren()) {
              all &= inFinalState(region, active);
            }
            if (all) {
              raised.add("done.state." + grand.id);
            }
          }
        }
      }
    }
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
      }
    }
  }

  private Configuration configuration(Collection<Node> active, Map<String, List<String>> history) {
    return new Configuration(new LinkedHashSet<>(Chart.ids(active)), history);
  }

  /** The active states {@code t} exits in {@code c}, in document order. */
  Set<Node> exitSet(ScTransition t, Configuration c) {
    Set<Node> exits = new LinkedHashSet<>();
    if (t.targets().isEmpty()) {
      return exits;
    }
    Node domain = domain(t, c);
    for (Node n : chart.nodes(c.active(), "active state")) {
      if (n.isDescendantOf(domain)) {
        exits.add(n);
      }
    }
    return exits;
  }

  /** The state whose descendants {@code t} exits and enters (SCXML's transition domain). */
  private Node domain(ScTransition t, Configuration c) {
    List<Node> targets = effectiveTargets(t.targets(), c.history());
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
    // The least common compound ancestor of the source and the targets.
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

  private void addDescendants(Node s, Set<Node> toEnter, Map<String, List<String>> history) {
    if (s.isHistory()) {
      List<String> remembered = history.getOrDefault(s.id, List.of());
      List<Node> targets =
          remembered.isEmpty()
              ? s.historyDefault
              : new ArrayList<>(chart.nodes(remembered, "remembered state"));
      Node parent = requireNonNull(s.parent);
      for (Node n : targets) {
        addDescendants(n, toEnter, history);
      }
      for (Node n : targets) {
        addAncestors(n, parent, toEnter, history);
      }
      return;
    }
    toEnter.add(s);
    if (s.isCompound()) {
      for (Node n : s.initial) {
        addDescendants(n, toEnter, history);
        addAncestors(n, s, toEnter, history);
      }
    } else if (s.isParallel()) {
      for (Node region : s.stateChildren()) {
        if (toEnter.stream().noneMatch(e -> e == region || e.isDescendantOf(region))) {
          addDescendants(region, toEnter, history);
        }
      }
    }
  }

  private void addAncestors(
      Node s, Node stop, Set<Node> toEnter, Map<String, List<String>> history) {
    for (Node anc : s.ancestorsUpTo(stop)) {
      if (anc == chart.root) {
        break;
      }
      toEnter.add(anc);
      if (anc.isParallel()) {
        for (Node region : anc.stateChildren()) {
          if (toEnter.stream().noneMatch(e -> e == region || e.isDescendantOf(region))) {
            addDescendants(region, toEnter, history);
          }
        }
      }
    }
  }
}

package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import org.jspecify.annotations.Nullable;

/** The state tree of a definition, checked and indexed, with document order and depth. */
final class Chart {

  /** A node of the tree; the root stands for the {@code <scxml>} element and is never active. */
  static final class Node {
    final String id;
    final ScNode.Kind kind;
    final @Nullable Node parent;
    final int order;
    final int depth;
    final List<ScAction> onEntry;
    final List<ScAction> onExit;
    final List<ScAction> defaultActions;
    final @Nullable ScData doneData;
    final List<Node> children = new ArrayList<>();
    final List<Node> initial = new ArrayList<>();
    final List<Node> historyDefault = new ArrayList<>();
    // Derived from children once the tree is built (the step semantics asks for them often).
    private List<Node> states = List.of();
    private List<Node> historyChildren = List.of();

    Node(String id, ScNode.Kind kind, @Nullable Node parent, int order, ScNode source) {
      this.id = id;
      this.kind = kind;
      this.parent = parent;
      this.order = order;
      this.depth = parent == null ? 0 : parent.depth + 1;
      this.onEntry = source.onEntry();
      this.onExit = source.onExit();
      this.defaultActions = source.defaultActions();
      this.doneData = source.doneData();
    }

    boolean isHistory() {
      return kind.isHistory();
    }

    boolean isParallel() {
      return kind == ScNode.Kind.PARALLEL;
    }

    boolean isFinal() {
      return kind == ScNode.Kind.FINAL;
    }

    /** A compound state or the root: one active child at a time. */
    boolean isCompound() {
      return kind == ScNode.Kind.STATE && !stateChildren().isEmpty();
    }

    boolean isAtomic() {
      return kind == ScNode.Kind.FINAL || (kind == ScNode.Kind.STATE && stateChildren().isEmpty());
    }

    List<Node> stateChildren() {
      return states;
    }

    List<Node> historyChildren() {
      return historyChildren;
    }

    void freeze() {
      states = children.stream().filter(c -> !c.isHistory()).toList();
      historyChildren = children.stream().filter(Node::isHistory).toList();
    }

    /** Whether this node is a proper descendant of {@code ancestor}. */
    boolean isDescendantOf(Node ancestor) {
      for (Node p = parent; p != null; p = p.parent) {
        if (p == ancestor) {
          return true;
        }
      }
      return false;
    }

    /** The proper ancestors of this node, nearest first, up to (not including) {@code stop}. */
    List<Node> ancestorsUpTo(@Nullable Node stop) {
      List<Node> result = new ArrayList<>();
      for (Node p = parent; p != null && p != stop; p = p.parent) {
        result.add(p);
      }
      return result;
    }

    @Override
    public String toString() {
      return id;
    }
  }

  static final Comparator<Node> DOCUMENT_ORDER = Comparator.comparingInt(n -> n.order);

  final Node root;
  final Map<String, Node> byId;
  final List<Node> histories;

  /**
   * @throws IllegalArgumentException if ids repeat, or an initial or history default does not name
   *     a descendant of its state (of its parent, for a history)
   */
  Chart(ScDefinition definition) {
    requireNonNull(definition, "definition");
    if (definition.states().isEmpty()) {
      throw new IllegalArgumentException(
          "chart '" + definition.name() + "' has no state; expected at least one");
    }
    ScNode top =
        new ScNode(
            "scxml",
            ScNode.Kind.STATE,
            definition.initial(),
            List.of(),
            List.of(),
            List.of(),
            definition.states());
    Map<String, Node> index = new LinkedHashMap<>();
    Map<Node, ScNode> sources = new LinkedHashMap<>();
    this.root = new Node("(root)", ScNode.Kind.STATE, null, 0, top);
    sources.put(root, top);
    int[] order = {1};
    for (ScNode child : top.children()) {
      add(child, root, index, sources, order);
    }
    this.byId = Collections.unmodifiableMap(index);
    root.freeze();
    for (Node n : index.values()) {
      n.freeze();
    }
    for (Map.Entry<Node, ScNode> e : sources.entrySet()) {
      resolve(e.getKey(), e.getValue());
    }
    this.histories = index.values().stream().filter(Node::isHistory).toList();
  }

  private static void add(
      ScNode source, Node parent, Map<String, Node> index, Map<Node, ScNode> sources, int[] order) {
    Node node = new Node(source.id(), source.kind(), parent, order[0]++, source);
    if (index.putIfAbsent(node.id, node) != null) {
      throw new IllegalArgumentException("state id '" + node.id + "' is used twice");
    }
    parent.children.add(node);
    sources.put(node, source);
    for (ScNode child : source.children()) {
      add(child, node, index, sources, order);
    }
  }

  private void resolve(Node node, ScNode source) {
    if (node.isCompound()) {
      List<String> ids = source.initial();
      if (ids.isEmpty()) {
        node.initial.add(node.stateChildren().get(0));
      } else {
        for (String id : ids) {
          Node target = node(id, "initial");
          boolean legal =
              target.isHistory()
                  ? target.parent == node && ids.size() == 1
                  : target.isDescendantOf(node);
          if (!legal) {
            throw new IllegalArgumentException(
                "initial '"
                    + id
                    + "' of '"
                    + node.id
                    + "' is not a state inside it nor (alone) one of its history pseudo-states");
          }
          node.initial.add(target);
        }
        requireTogether(node.initial, "initial " + ids + " of '" + node.id + "'");
      }
    }
    if (node.isHistory()) {
      // Parents come before their children in the map, so the parent's initial is resolved.
      Node parent = requireNonNull(node.parent);
      if (parent == root) {
        throw new IllegalArgumentException(
            "history '" + node.id + "' is at the top level; expected it inside a state");
      }
      for (String id : source.historyDefault()) {
        Node target = node(id, "history default");
        if (target.isHistory() || !target.isDescendantOf(parent)) {
          throw new IllegalArgumentException(
              "history default '"
                  + id
                  + "' of '"
                  + node.id
                  + "' is not a state inside '"
                  + parent.id
                  + "'");
        }
        node.historyDefault.add(target);
      }
      if (node.historyDefault.isEmpty()) {
        if (parent.isParallel()) {
          node.historyDefault.addAll(parent.stateChildren());
        } else if (parent.isCompound()) {
          node.historyDefault.addAll(parent.initial);
        } else {
          throw new IllegalArgumentException(
              "history '"
                  + node.id
                  + "' is in '"
                  + parent.id
                  + "', which has no state to remember");
        }
      }
    }
  }

  /**
   * Checks that {@code targets} can be entered together: no two of them are the same state, one
   * inside the other, or in one compound state (a history stands for its parent's states).
   *
   * @throws IllegalArgumentException naming {@code what} and the two that cannot
   */
  static void requireTogether(List<Node> targets, String what) {
    for (int i = 0; i < targets.size(); i++) {
      for (int j = i + 1; j < targets.size(); j++) {
        Node a = targets.get(i);
        Node b = targets.get(j);
        Node x = a.isHistory() ? requireNonNull(a.parent) : a;
        Node y = b.isHistory() ? requireNonNull(b.parent) : b;
        Node common = x.parent;
        while (common != null && !(y.isDescendantOf(common))) {
          common = common.parent;
        }
        boolean nested = x == y || x.isDescendantOf(y) || y.isDescendantOf(x);
        if (nested || common == null || !common.isParallel()) {
          throw new IllegalArgumentException(
              what
                  + ": '"
                  + a.id
                  + "' and '"
                  + b.id
                  + "' cannot be active together; expected states in different regions of a"
                  + " parallel state");
        }
      }
    }
  }

  /** The node {@code id}; {@code what} says what named it, for the message. */
  Node node(String id, String what) {
    Node n = byId.get(requireNonNull(id, what));
    if (n == null) {
      throw new IllegalArgumentException(
          what + " '" + id + "' is not a state of the chart; states: " + byId.keySet());
    }
    return n;
  }

  /** The nodes of {@code ids}, in document order. */
  TreeSet<Node> nodes(Collection<String> ids, String what) {
    TreeSet<Node> result = new TreeSet<>(DOCUMENT_ORDER);
    for (String id : ids) {
      result.add(node(id, what));
    }
    return result;
  }

  static List<String> ids(Collection<Node> nodes) {
    List<String> ids = new ArrayList<>(nodes.size());
    for (Node n : nodes) {
      ids.add(n.id);
    }
    return ids;
  }
}

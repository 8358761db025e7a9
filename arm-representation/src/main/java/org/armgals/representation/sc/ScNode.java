package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.Arrays;
import java.util.List;
import org.jspecify.annotations.Nullable;

/**
 * A state of a statechart definition ({@code <state>}, {@code <parallel>}, {@code <final>} or
 * {@code <history>} in SCXML) with its children.
 *
 * <p>A {@link Kind#STATE} with state children is compound: it enters {@link #initial()} (its first
 * child when empty; a history child enters what the history says) by default; without them it is
 * atomic. A {@link Kind#PARALLEL} has orthogonal regions, all active together. A history
 * pseudo-state remembers the active children ({@link Kind#SHALLOW_HISTORY}) or atomic descendants
 * ({@link Kind#DEEP_HISTORY}) of its parent when the parent is exited; a transition to it restores
 * them, or enters {@link #historyDefault()} (its parent's initial state when empty) the first time.
 *
 * @param id unique in the chart
 * @param kind what the node is
 * @param initial for a compound state, what it enters by default: one descendant or history child,
 *     or descendants in different regions of a parallel state (SCXML's {@code initial="a b"});
 *     empty for its first child
 * @param onEntry actions on entry, in order
 * @param onExit actions on exit, in order
 * @param historyDefault for a history pseudo-state, where it leads before anything is remembered
 * @param children sub-states and history pseudo-states, in document order
 * @param defaultActions the content of the default transition: for a compound state with an {@code
 *     initial}, that of its {@code <initial>} transition, run after its entry actions when it is
 *     entered by default; for a history with a default, that of its default transition, run after
 *     its parent's entry actions when the default is taken
 * @param doneData for a final state, the data of the {@code done.state} event entering it raises
 *     for its parent ({@code <donedata>}); null for none
 */
public record ScNode(
    String id,
    Kind kind,
    List<String> initial,
    List<ScAction> onEntry,
    List<ScAction> onExit,
    List<String> historyDefault,
    List<ScNode> children,
    List<ScAction> defaultActions,
    @Nullable ScData doneData) {

  /** What a node is. */
  public enum Kind {
    /** An atomic state, or a compound one when it has state children. */
    STATE,
    /** A state whose children are orthogonal regions. */
    PARALLEL,
    /** A final state: entering it completes its parent. */
    FINAL,
    /** Remembers the active children of its parent. */
    SHALLOW_HISTORY,
    /** Remembers the active atomic descendants of its parent. */
    DEEP_HISTORY;

    /** Whether this kind is a history pseudo-state. */
    public boolean isHistory() {
      return this == SHALLOW_HISTORY || this == DEEP_HISTORY;
    }
  }

  /**
   * Checks the node.
   *
   * @throws IllegalArgumentException if the id is not a name, or the node has parts its kind does
   *     not allow (children of a final or history, an initial on a non-compound state, actions on a
   *     history, a history default on a state, done data on anything but a final state)
   */
  public ScNode {
    ScNames.requireName(id, "state id");
    requireNonNull(kind, "kind");
    initial = ScNames.requireNames(initial, "initial of '" + id + "'");
    onEntry = List.copyOf(requireNonNull(onEntry, "onEntry"));
    onExit = List.copyOf(requireNonNull(onExit, "onExit"));
    historyDefault = ScNames.requireNames(historyDefault, "history default of '" + id + "'");
    children = List.copyOf(requireNonNull(children, "children"));
    defaultActions = List.copyOf(requireNonNull(defaultActions, "defaultActions"));
    if ((kind == Kind.FINAL || kind.isHistory()) && !children.isEmpty()) {
      throw new IllegalArgumentException(kind + " '" + id + "' has children; expected none");
    }
    if (kind.isHistory() && !(onEntry.isEmpty() && onExit.isEmpty())) {
      throw new IllegalArgumentException("history '" + id + "' has actions; expected none");
    }
    if (!kind.isHistory() && !historyDefault.isEmpty()) {
      throw new IllegalArgumentException(
          kind + " '" + id + "' has a history default; only a history has one");
    }
    if (!defaultActions.isEmpty() && initial.isEmpty() && historyDefault.isEmpty()) {
      throw new IllegalArgumentException(
          kind
              + " '"
              + id
              + "' has default actions; only a state with an initial or a history with a default"
              + " has them");
    }
    if (doneData != null && kind != Kind.FINAL) {
      throw new IllegalArgumentException(
          kind + " '" + id + "' has done data; only a final state has it");
    }
    if (!initial.isEmpty()) {
      if (kind != Kind.STATE || children.stream().allMatch(c -> c.kind().isHistory())) {
        throw new IllegalArgumentException(
            kind + " '" + id + "' has initial '" + initial + "'; only a compound state has one");
      }
    }
  }

  /** A node without done data. */
  public ScNode(
      String id,
      Kind kind,
      List<String> initial,
      List<ScAction> onEntry,
      List<ScAction> onExit,
      List<String> historyDefault,
      List<ScNode> children,
      List<ScAction> defaultActions) {
    this(id, kind, initial, onEntry, onExit, historyDefault, children, defaultActions, null);
  }

  /** A node without default actions or done data. */
  public ScNode(
      String id,
      Kind kind,
      List<String> initial,
      List<ScAction> onEntry,
      List<ScAction> onExit,
      List<String> historyDefault,
      List<ScNode> children) {
    this(id, kind, initial, onEntry, onExit, historyDefault, children, List.of(), null);
  }

  /** A state: atomic without children, compound with them. */
  public static ScNode state(String id, ScNode... children) {
    return new ScNode(
        id, Kind.STATE, List.of(), List.of(), List.of(), List.of(), Arrays.asList(children));
  }

  /** A parallel state whose children are its regions. */
  public static ScNode parallel(String id, ScNode... regions) {
    return new ScNode(
        id, Kind.PARALLEL, List.of(), List.of(), List.of(), List.of(), Arrays.asList(regions));
  }

  /** A final state. */
  public static ScNode finalState(String id) {
    return new ScNode(id, Kind.FINAL, List.of(), List.of(), List.of(), List.of(), List.of());
  }

  /** A history pseudo-state, deep or shallow, leading to {@code defaults} the first time. */
  public static ScNode history(String id, boolean deep, String... defaults) {
    return new ScNode(
        id,
        deep ? Kind.DEEP_HISTORY : Kind.SHALLOW_HISTORY,
        List.of(),
        List.of(),
        List.of(),
        Arrays.asList(defaults),
        List.of());
  }

  /**
   * This node entering {@code initial} by default: one descendant or history child, or descendants
   * in different regions of a parallel state.
   */
  public ScNode withInitial(String... initial) {
    return new ScNode(
        id,
        kind,
        Arrays.asList(initial),
        onEntry,
        onExit,
        historyDefault,
        children,
        defaultActions,
        doneData);
  }

  /** This node with {@code actions} on entry. */
  public ScNode onEntry(ScAction... actions) {
    return new ScNode(
        id,
        kind,
        initial,
        Arrays.asList(actions),
        onExit,
        historyDefault,
        children,
        defaultActions,
        doneData);
  }

  /** This node with {@code actions} on exit. */
  public ScNode onExit(ScAction... actions) {
    return new ScNode(
        id,
        kind,
        initial,
        onEntry,
        Arrays.asList(actions),
        historyDefault,
        children,
        defaultActions,
        doneData);
  }

  /**
   * This node with {@code actions} as the content of its default transition (its {@code <initial>}
   * transition, or its default as a history).
   */
  public ScNode onDefault(ScAction... actions) {
    return new ScNode(
        id,
        kind,
        initial,
        onEntry,
        onExit,
        historyDefault,
        children,
        Arrays.asList(actions),
        doneData);
  }

  /**
   * This final state with {@code data} as the data of the {@code done.state} event entering it
   * raises ({@code <donedata>}).
   */
  public ScNode withDoneData(ScData data) {
    return new ScNode(
        id,
        kind,
        initial,
        onEntry,
        onExit,
        historyDefault,
        children,
        defaultActions,
        requireNonNull(data, "data"));
  }
}

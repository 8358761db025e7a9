package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.Set;

/**
 * What an entity notifies its behavioral meta of, and at which grain (paper §2.3, §3.3): the entity
 * chooses, and its meta may change the choice at run time ({@link Adaptation.SetNotification}).
 *
 * <p>After each step: an {@link ActionEvent} if {@code actions} and the behavior is in {@code
 * behaviors} (empty: all); a {@link StateEvent} if {@code states} and what is observed of the new
 * state, restricted to {@code observed} (empty: everything), differs from what was observed after
 * the previous notified state; a {@link ThresholdEvent} for each threshold crossed, always.
 * Failures and reflective requests are always notified.
 *
 * @param states whether to notify states
 * @param actions whether to notify actions
 * @param observed the grain of state events: the observed names they carry; empty for all
 * @param behaviors the behaviors whose actions are notified; empty for all
 * @param thresholds the thresholds watched
 * @param depth the grain of state events of a statechart entity: the active states down to this
 *     depth (1: top-level states only; a composite state stands for all its substates); 0 for the
 *     finest (every active leaf). Ignored by other representations.
 */
public record NotificationPolicy(
    boolean states,
    boolean actions,
    Set<String> observed,
    Set<String> behaviors,
    List<Threshold> thresholds,
    int depth) {

  /** Checks and copies the components. */
  public NotificationPolicy {
    observed = Set.copyOf(requireNonNull(observed, "observed"));
    behaviors = Set.copyOf(requireNonNull(behaviors, "behaviors"));
    thresholds = List.copyOf(requireNonNull(thresholds, "thresholds"));
    if (depth < 0) {
      throw new IllegalArgumentException("depth must be >= 0 (0: finest), was " + depth);
    }
  }

  /** Complete state events and all actions. */
  public static NotificationPolicy all() {
    return new NotificationPolicy(true, true, Set.of(), Set.of(), List.of(), 0);
  }

  /** Complete state events only. */
  public static NotificationPolicy statesOnly() {
    return new NotificationPolicy(true, false, Set.of(), Set.of(), List.of(), 0);
  }

  /** Action events only. */
  public static NotificationPolicy actionsOnly() {
    return new NotificationPolicy(false, true, Set.of(), Set.of(), List.of(), 0);
  }

  /** Nothing but thresholds, failures and reflective requests. */
  public static NotificationPolicy quiet() {
    return new NotificationPolicy(false, false, Set.of(), Set.of(), List.of(), 0);
  }

  /** This policy with state events restricted to the {@code names} observed (a coarser grain). */
  public NotificationPolicy observing(String... names) {
    return new NotificationPolicy(states, actions, Set.of(names), behaviors, thresholds, depth);
  }

  /** This policy with statechart state events at {@code coarseness} (0: finest). */
  public NotificationPolicy atDepth(int coarseness) {
    return new NotificationPolicy(states, actions, observed, behaviors, thresholds, coarseness);
  }

  /** This policy with these thresholds watched. */
  public NotificationPolicy watching(Threshold... watched) {
    return new NotificationPolicy(states, actions, observed, behaviors, List.of(watched), depth);
  }
}

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
 */
public record NotificationPolicy(
    boolean states,
    boolean actions,
    Set<String> observed,
    Set<String> behaviors,
    List<Threshold> thresholds) {

  /** Checks and copies the components. */
  public NotificationPolicy {
    observed = Set.copyOf(requireNonNull(observed, "observed"));
    behaviors = Set.copyOf(requireNonNull(behaviors, "behaviors"));
    thresholds = List.copyOf(requireNonNull(thresholds, "thresholds"));
  }

  /** Complete state events and all actions. */
  public static NotificationPolicy all() {
    return new NotificationPolicy(true, true, Set.of(), Set.of(), List.of());
  }

  /** Complete state events only. */
  public static NotificationPolicy statesOnly() {
    return new NotificationPolicy(true, false, Set.of(), Set.of(), List.of());
  }

  /** Action events only. */
  public static NotificationPolicy actionsOnly() {
    return new NotificationPolicy(false, true, Set.of(), Set.of(), List.of());
  }

  /** Nothing but thresholds, failures and reflective requests. */
  public static NotificationPolicy quiet() {
    return new NotificationPolicy(false, false, Set.of(), Set.of(), List.of());
  }

  /** This policy with state events restricted to the {@code names} observed (a coarser grain). */
  public NotificationPolicy observing(String... names) {
    return new NotificationPolicy(states, actions, Set.of(names), behaviors, thresholds);
  }

  /** This policy with these thresholds watched. */
  public NotificationPolicy watching(Threshold... watched) {
    return new NotificationPolicy(states, actions, observed, behaviors, List.of(watched));
  }
}

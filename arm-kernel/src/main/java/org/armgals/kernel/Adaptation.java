package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import org.jspecify.annotations.Nullable;

/** What an adaptation request asks a base entity to do (flow 3 of §3.1). */
public sealed interface Adaptation {

  /** Notify this from now on: which events, at which grain, with which thresholds. */
  record SetNotification(NotificationPolicy policy) implements Adaptation {
    /** Checks the policy. */
    public SetNotification {
      requireNonNull(policy, "policy");
    }
  }

  /**
   * Apply the behavior named {@code behavior} with {@code input}, as if it had been called: the
   * entity notifies the step as any other.
   */
  record ApplyBehavior(String behavior, @Nullable Object input) implements Adaptation {
    /** Checks the name. */
    public ApplyBehavior {
      requireNonNull(behavior, "behavior");
    }
  }
}

package org.armgals.maam;

import org.jspecify.annotations.Nullable;

/**
 * What an inhibitor or a suppressor remembers between cycles. Kept by the robot per connector, so a
 * rescheduling does not cut a hold short.
 */
final class ConnectorState {

  static final long NEVER = Long.MIN_VALUE;

  /** The time of the last cycle its source emitted in. */
  long lastActive = NEVER;

  /** A suppressor's last source signal. */
  @Nullable Signal latched;

  /** Whether a cycle at {@code now} is within {@code holdNanos} of the last active one. */
  boolean holds(long now, long holdNanos) {
    return lastActive != NEVER && now - lastActive <= holdNanos;
  }
}

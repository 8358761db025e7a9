package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.time.Duration;

/** The check of a connector's hold time, shared by {@link Inhibitor} and {@link Suppressor}. */
final class Holds {

  private Holds() {}

  static Duration check(Duration hold) {
    requireNonNull(hold, "hold");
    if (hold.isNegative()) {
      throw new IllegalArgumentException("hold " + hold + ": expected zero or positive");
    }
    return hold;
  }
}

package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.time.Duration;

/**
 * How often a behavioral meta may adapt one base entity (anti-thrashing, paper §2.3): at least
 * {@code minDwell} between two adaptations of an entity, and at most {@code maxAdaptations} in any
 * {@code window}. Hysteresis is the third tool: see {@link Threshold}. A held-back adaptation is
 * counted ({@link ModelView#suppressedAdaptations()}), not queued.
 *
 * @param minDwell the least time an entity stays in what an adaptation made of it, zero or more
 * @param maxAdaptations the most adaptations of one entity in a window, at least 1
 * @param window the window of the rate limit, positive
 */
public record Damping(Duration minDwell, int maxAdaptations, Duration window) {

  /** Checks the components. */
  public Damping {
    requireNonNull(minDwell, "minDwell");
    requireNonNull(window, "window");
    if (minDwell.isNegative()) {
      throw new IllegalArgumentException("minDwell must be >= 0, was " + minDwell);
    }
    if (maxAdaptations < 1) {
      throw new IllegalArgumentException("maxAdaptations must be >= 1, was " + maxAdaptations);
    }
    if (window.isNegative() || window.isZero()) {
      throw new IllegalArgumentException("window must be positive, was " + window);
    }
  }

  /** No damping: no dwell time and no practical rate limit. */
  public static Damping none() {
    return new Damping(Duration.ZERO, Integer.MAX_VALUE, Duration.ofNanos(1));
  }
}

package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.ArrayDeque;

/**
 * The damping of the adaptations of one base entity: a minimum dwell time and a rate limit over a
 * sliding window. Confined to its behavioral meta's object.
 */
final class Governor {
  private final long dwellNanos;
  private final int max;
  private final long windowNanos;
  private final ArrayDeque<Long> recent = new ArrayDeque<>();
  private boolean adapted;
  private long last;
  private long suppressed;

  Governor(Damping damping) {
    requireNonNull(damping, "damping");
    this.dwellNanos = damping.minDwell().toNanos();
    this.max = damping.maxAdaptations();
    this.windowNanos = damping.window().toNanos();
  }

  /** Whether an adaptation may be sent at {@code now}; if so it is counted as sent. */
  boolean tryAdapt(long now) {
    while (!recent.isEmpty() && now - recent.peekFirst() >= windowNanos) {
      recent.pollFirst();
    }
    if ((adapted && now - last < dwellNanos) || recent.size() >= max) {
      suppressed++;
      return false;
    }
    adapted = true;
    last = now;
    recent.addLast(now);
    return true;
  }

  long suppressed() {
    return suppressed;
  }
}

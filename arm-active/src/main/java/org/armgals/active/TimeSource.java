package org.armgals.active;

/**
 * Where the runtime reads time (style rule: time is injected). Nanoseconds from an arbitrary
 * origin, never decreasing.
 */
@FunctionalInterface
public interface TimeSource {

  /** Now, in nanoseconds from this source's origin. */
  long nanoTime();

  /** The machine's monotonic clock ({@link System#nanoTime()}). */
  static TimeSource system() {
    return System::nanoTime;
  }
}

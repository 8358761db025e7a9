package org.armgals.active;

/** How an active object is driven, chosen once at creation (paper §5.3). */
public enum Mode {
  /**
   * Events are processed one at a time as they arrive, in arrival order per sender, skipping those
   * that are not processable. Dormant (no thread) when nothing is processable.
   */
  ASYNCHRONOUS,
  /**
   * The object is a reactive object: at each release of its {@link Clock} it takes every event
   * waiting at that instant and processes them; what it emits is seen by others from the next
   * release.
   */
  SYNCHRONOUS
}

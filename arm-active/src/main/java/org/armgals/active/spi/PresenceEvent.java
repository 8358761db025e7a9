package org.armgals.active.spi;

import static java.util.Objects.requireNonNull;

import java.time.Duration;

/** A change in the set of runtimes present, as one runtime's presence saw it. */
public sealed interface PresenceEvent {

  /** The runtime the change is about. */
  String runtime();

  /** The runtime beat for the first time, or again after it was lost. */
  record Joined(String runtime) implements PresenceEvent {
    /** The event; {@code runtime} must not be null. */
    public Joined {
      requireNonNull(runtime, "runtime");
    }
  }

  /** The runtime said it is leaving (its presence was closed). */
  record Left(String runtime) implements PresenceEvent {
    /** The event; {@code runtime} must not be null. */
    public Left {
      requireNonNull(runtime, "runtime");
    }
  }

  /**
   * The runtime fell silent for {@code silence}, longer than the missed beats allow: its JVM was
   * killed or hangs, or its link to the broker is down. Requests waiting for its answers will not
   * get them.
   */
  record Lost(String runtime, Duration silence) implements PresenceEvent {
    /** The event; neither {@code runtime} nor {@code silence} may be null. */
    public Lost {
      requireNonNull(runtime, "runtime");
      requireNonNull(silence, "silence");
    }
  }
}

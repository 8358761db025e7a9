package org.armgals.examples.plot;

import static java.util.Objects.requireNonNull;

/**
 * Something that happened at one moment of a run, for a time line.
 *
 * @param seconds when, in simulated seconds from the start
 * @param kind what kind of thing (one row of the time line per kind)
 */
public record Marker(double seconds, String kind) {

  /** Checks the time and the kind. */
  public Marker {
    requireNonNull(kind, "kind");
    if (!Double.isFinite(seconds) || seconds < 0) {
      throw new IllegalArgumentException("a marker's time must be >= 0, not " + seconds);
    }
  }
}

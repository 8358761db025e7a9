package org.armgals.examples.run;

import static java.util.Objects.requireNonNull;

import java.util.List;

/**
 * What a run printed at its end, as name and value pairs in order (distance, energy used,
 * adaptations, …).
 *
 * @param entries the figures, in the order they are printed
 */
public record Summary(List<Entry> entries) {

  /** One figure of a summary. */
  public record Entry(String name, String value) {
    /** Checks that both are present. */
    public Entry {
      requireNonNull(name, "name");
      requireNonNull(value, "value");
    }
  }

  /** Copies the list. */
  public Summary {
    entries = List.copyOf(entries);
  }
}

package org.armgals.maam;

import static java.util.Objects.requireNonNull;

/**
 * A connection inside a {@link Schema}: the signal emitted on output {@code from} is the signal on
 * input {@code to} in the same cycle, so {@code from}'s module is scheduled before {@code to}'s.
 *
 * @param from an output port
 * @param to an input port whose type accepts {@code from}'s
 */
public record Wire(PortRef from, PortRef to) {

  /** Checks for nulls. */
  public Wire {
    requireNonNull(from, "from");
    requireNonNull(to, "to");
  }

  @Override
  public String toString() {
    return from + " -> " + to;
  }
}

package org.armgals.maam;

import static java.util.Objects.requireNonNull;

/**
 * A signal a robot's module emitted in a cycle, after suppression: what {@link
 * AbstractRobot#emissions()} lists for a robot's {@link AbstractRobot#observe() observation}.
 *
 * @param port the output port
 * @param signal what its readers saw
 */
public record Emission(PortRef port, Signal signal) {

  /** Checks for nulls. */
  public Emission {
    requireNonNull(port, "port");
    requireNonNull(signal, "signal");
  }
}

package org.armgals.maam;

import static java.util.Objects.requireNonNull;

/**
 * Branches output {@code source} to input {@code target}, typically of a module in another schema:
 * the target reads what the source emitted in the same cycle, as through a {@link Wire}, and the
 * source keeps its other readers.
 *
 * @param source an output port
 * @param target an input port, fed by nothing else, whose type accepts the source's
 */
public record Derivator(PortRef source, PortRef target) implements Connector {

  /** Checks for nulls. */
  public Derivator {
    requireNonNull(source, "source");
    requireNonNull(target, "target");
  }

  @Override
  public String toString() {
    return "Derivator(" + source + " -> " + target + ")";
  }
}

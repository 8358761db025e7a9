package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.time.Duration;

/**
 * Blocks input {@code target} while output {@code source} is active, and for {@code hold} after
 * (figure 5: B inhibits the input 1 of A). The source is active in a cycle when its module emits on
 * it; the target input then reads no signal in every cycle whose time is at most {@code hold} after
 * the last active one (a zero hold blocks only in active cycles).
 *
 * @param source an output port
 * @param target an input port
 * @param hold zero or positive
 */
public record Inhibitor(PortRef source, PortRef target, Duration hold) implements Connector {

  /** Checks for nulls and the hold. */
  public Inhibitor {
    requireNonNull(source, "source");
    requireNonNull(target, "target");
    Holds.check(hold);
  }

  @Override
  public String toString() {
    return "Inhibitor(" + source + " -| " + target + ", hold " + hold + ")";
  }
}

package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.time.Duration;

/**
 * Replaces output {@code target} with output {@code source} (figure 5: C suppresses the output 2 of
 * A). When the source's module emits on it, that signal is latched and is what the target's readers
 * see, instead of what the target's module emitted, in every cycle whose time is at most {@code
 * hold} after the last emission (Brooks' suppressor, whose wire keeps the last message for its
 * period); after that the target's own signal passes again.
 *
 * @param source an output port whose type the target accepts
 * @param target an output port
 * @param hold zero or positive
 */
public record Suppressor(PortRef source, PortRef target, Duration hold) implements Connector {

  /** Checks for nulls and the hold. */
  public Suppressor {
    requireNonNull(source, "source");
    requireNonNull(target, "target");
    Holds.check(hold);
  }

  @Override
  public String toString() {
    return "Suppressor(" + source + " -S " + target + ", hold " + hold + ")";
  }
}

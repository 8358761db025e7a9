package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import org.armgals.active.Address;
import org.armgals.active.Event;
import org.jspecify.annotations.Nullable;

/**
 * A base-level event for an entity: its {@code process} dispatches {@code trigger} with {@code
 * input} to its activation. See {@link Entity#send}.
 *
 * @param sender who sent it, {@code null} outside any active object
 * @param destination the entity
 * @param trigger the trigger (a method name, a transition label, a statechart event)
 * @param input a simple value if the event is to cross runtimes, or {@code null}
 */
public record Stimulus(
    @Nullable Address sender, Address destination, String trigger, @Nullable Object input)
    implements Event {

  /** Checks the components. */
  public Stimulus {
    requireNonNull(destination, "destination");
    requireNonNull(trigger, "trigger");
  }
}

package org.armgals.gals;

import static java.util.Objects.requireNonNull;

import org.armgals.active.Address;
import org.armgals.active.Event;
import org.jspecify.annotations.Nullable;

/**
 * The event that carries a payload to a reactive entity, from another entity or from outside any.
 * In one runtime it is handed over in memory; to an entity of another runtime it crosses the
 * broker, so a {@code JmsTransport} that carries events between islands allows it and the types of
 * the payloads ({@code allow(Emission.class, Reading.class)}): see "Islands in several runtimes" in
 * docs/gals-guide.md.
 *
 * @param sender the entity that emitted it, or {@code null} from outside any entity
 * @param destination the receiving entity's address
 * @param payload what the receiver finds in {@link CycleContext#inputs()}
 */
public record Emission(@Nullable Address sender, Address destination, Object payload)
    implements Event {
  /** Checks that the destination and the payload are there. */
  public Emission {
    requireNonNull(destination, "destination");
    requireNonNull(payload, "payload");
  }
}

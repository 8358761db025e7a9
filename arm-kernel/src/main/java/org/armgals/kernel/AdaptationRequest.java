package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import org.armgals.active.Address;
import org.armgals.active.Event;

/**
 * An adaptation request from a behavioral meta to one of its base entities (flow 3 of §3.1).
 * Versions increase per entity; the entity applies a request only if its version is above the last
 * it applied, and answers every request with an {@link AdaptationAck}.
 *
 * @param sender the behavioral meta
 * @param destination the base entity
 * @param version the request's version, from 1
 * @param adaptation what to do
 */
public record AdaptationRequest(
    Address sender, Address destination, long version, Adaptation adaptation) implements Event {

  /** Checks the components. */
  public AdaptationRequest {
    requireNonNull(sender, "sender");
    requireNonNull(destination, "destination");
    requireNonNull(adaptation, "adaptation");
    if (version < 1) {
      throw new IllegalArgumentException("version must be >= 1, was " + version);
    }
  }
}

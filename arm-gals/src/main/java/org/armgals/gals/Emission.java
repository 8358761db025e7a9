package org.armgals.gals;

import static java.util.Objects.requireNonNull;

import org.armgals.active.Address;
import org.armgals.active.Event;
import org.jspecify.annotations.Nullable;

/** A payload sent to a reactive entity, by another entity or from outside any. */
record Emission(@Nullable Address sender, Address destination, Object payload) implements Event {
  Emission {
    requireNonNull(destination, "destination");
    requireNonNull(payload, "payload");
  }
}

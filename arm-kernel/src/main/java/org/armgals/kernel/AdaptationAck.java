package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import org.armgals.active.Address;
import org.armgals.active.Event;
import org.jspecify.annotations.Nullable;

/**
 * A base entity's answer to an {@link AdaptationRequest}: the meta learns which version the entity
 * applied ({@link ModelView#appliedVersion()}).
 *
 * @param sender the base entity
 * @param destination the behavioral meta that sent the request
 * @param version the request's version
 * @param applied whether it was applied
 * @param failure why not, when it was not: the failure's message, or that a later version was
 *     already applied
 */
public record AdaptationAck(
    Address sender, Address destination, long version, boolean applied, @Nullable String failure)
    implements Event {

  /** Checks the components. */
  public AdaptationAck {
    requireNonNull(sender, "sender");
    requireNonNull(destination, "destination");
    if (applied != (failure == null)) {
      throw new IllegalArgumentException(
          "a failure is given exactly when not applied; applied="
              + applied
              + ", failure="
              + failure);
    }
  }
}

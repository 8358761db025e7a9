package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import org.armgals.active.Address;
import org.armgals.active.Event;

/**
 * A behavioral meta's request for a complete {@link StateEvent}, sent when its model of the entity
 * missed a notification (a gap in the sequence numbers) or could not replay an action. Resync is
 * level-triggered: the meta asks again while its model stays out of sync.
 *
 * @param sender the behavioral meta
 * @param destination the base entity
 * @param lastSeq the last sequence number the model integrated (0 if none)
 */
public record ResyncRequest(Address sender, Address destination, long lastSeq) implements Event {

  /** Checks the components. */
  public ResyncRequest {
    requireNonNull(sender, "sender");
    requireNonNull(destination, "destination");
  }
}

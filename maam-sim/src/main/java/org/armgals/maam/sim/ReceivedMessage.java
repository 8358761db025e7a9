package org.armgals.maam.sim;

import static java.util.Objects.requireNonNull;

import org.armgals.maam.spi.Leg;

/**
 * A message from a bound neighbour, received through the binding of two legs.
 *
 * @param from the sending atom
 * @param fromLeg the leg it sent through
 * @param toLeg the leg of the receiving atom it arrived on
 * @param sentNanos the virtual time it was sent (ns)
 * @param payload what was sent
 */
public record ReceivedMessage(int from, Leg fromLeg, Leg toLeg, long sentNanos, String payload) {
  /** Checks for nulls. */
  public ReceivedMessage {
    requireNonNull(fromLeg, "fromLeg");
    requireNonNull(toLeg, "toLeg");
    requireNonNull(payload, "payload");
  }
}

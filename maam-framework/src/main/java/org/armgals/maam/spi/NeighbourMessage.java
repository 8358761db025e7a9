package org.armgals.maam.spi;

import static java.util.Objects.requireNonNull;

/**
 * A message between bound atoms, carried through a bound leg: sent on {@link Atom#SEND} with the
 * leg it leaves by, read from {@link Atom#INBOX} with the leg it came in by (the sender's id is in
 * that leg's {@link Atom#binding} sensor).
 *
 * @param leg the leg the message leaves or arrives by
 * @param payload the content, opaque to the body
 */
public record NeighbourMessage(Leg leg, String payload) {

  /** Checks for nulls. */
  public NeighbourMessage {
    requireNonNull(leg, "leg");
    requireNonNull(payload, "payload");
  }
}

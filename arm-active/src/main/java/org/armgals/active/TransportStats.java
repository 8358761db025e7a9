package org.armgals.active;

/**
 * A transport's figures, part of {@link RuntimeStats} and of the runtime's MBean. A transport
 * shared by several runtimes reports the same figures to each.
 *
 * <p>Every inbound message lands in exactly one of {@code received} (each event of a batch counts
 * once), {@code rejected}, {@code duplicates} or {@code unmatched}; a message that never arrived is
 * counted in {@code lost} by its receiver when the next one of its route does. On each route (the
 * events, requests and answers one transport sends to one runtime on one topic), what the sender
 * counted in {@code sent} is, at its receiver, received, rejected or lost, exactly; a message the
 * broker delivers again (at least once, after a restart) is counted in {@code duplicates} beyond
 * that.
 *
 * @param sent events, published events, requests and answers handed to the broker (each event of a
 *     batch counts once)
 * @param received events, published events, requests and answers taken from the broker and handed
 *     to an object, a subscription or a waiting future
 * @param batches messages that carried more than one event
 * @param rejected inbound messages refused (undecodable, a type not allowed, oversized, missing
 *     properties, or no object to take them): the dead-letter count
 * @param lost messages of a route that never arrived, found by the gap in the route's sequence
 *     numbers when a later message of the route arrived
 * @param duplicates messages of an at-least-once route that arrived again and were dropped
 * @param unmatched answers that no request waits for: late (after the reply timeout), repeated, or
 *     of a correlation number this transport never gave
 * @param unsent events, requests and answers this transport accepted but could not hand to the
 *     broker: dropped by its full outbound queue, or refused by the broker on an at-most-once route
 */
public record TransportStats(
    long sent,
    long received,
    long batches,
    long rejected,
    long lost,
    long duplicates,
    long unmatched,
    long unsent) {

  /** The figures of no transport, or one that counts nothing. */
  public static final TransportStats NONE = new TransportStats(0, 0, 0, 0, 0, 0, 0, 0);
}

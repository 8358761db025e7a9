package org.armgals.active;

/**
 * A transport's figures, part of {@link RuntimeStats} and of the runtime's MBean. A transport
 * shared by several runtimes reports the same figures to each.
 *
 * @param sent events, published events, requests and answers handed to the broker (each event of a
 *     batch counts once)
 * @param received events, published events, requests and answers taken from the broker and handed
 *     to an object, a subscription or a waiting future
 * @param batches messages that carried more than one event
 * @param rejected inbound messages refused (undecodable, a type not allowed, oversized, missing
 *     properties, or no object to take them): the dead-letter count
 */
public record TransportStats(long sent, long received, long batches, long rejected) {

  /** The figures of no transport, or one that counts nothing. */
  public static final TransportStats NONE = new TransportStats(0, 0, 0, 0);
}

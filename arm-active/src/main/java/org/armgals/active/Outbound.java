package org.armgals.active;

import java.util.Map;
import org.jspecify.annotations.Nullable;

/**
 * One message, or one event of a batch, waiting for the transport's sender thread: its topic, its
 * encoded value and its properties. Immutable.
 *
 * @param topic where it goes
 * @param batchKey events with the same non-null key may share a message (same topic, same
 *     destination runtime); null: always alone
 * @param value the encoded value (see {@link WireCodec#encodeValue})
 * @param properties its JMS properties
 */
record Outbound(
    JmsTransport.Topic topic,
    @Nullable String batchKey,
    byte[] value,
    Map<String, Object> properties) {

  /** Stops the sender thread. */
  static final Outbound STOP = new Outbound(JmsTransport.Topic.ENTITY, null, new byte[0], Map.of());
}

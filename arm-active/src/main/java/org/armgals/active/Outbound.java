package org.armgals.active;

import java.util.Map;
import org.jspecify.annotations.Nullable;

/**
 * One message, or one event of a batch, waiting for the transport's sender thread: its topic, its
 * encoded value and its properties. Immutable.
 *
 * @param topic where it goes
 * @param route the stream it keeps its order in (topic and destination runtime); null: none
 * @param batchable whether it may share a message with the events before and after it on its route
 * @param value the encoded value (see {@link WireCodec#encodeValue})
 * @param properties its JMS properties
 */
record Outbound(
    JmsTransport.Topic topic,
    @Nullable String route,
    boolean batchable,
    byte[] value,
    Map<String, Object> properties) {

  /** Stops the sender thread. */
  static final Outbound STOP =
      new Outbound(JmsTransport.Topic.ENTITY, null, false, new byte[0], Map.of());

  /** The route of what goes to {@code runtime} on {@code topic}. */
  static String route(JmsTransport.Topic topic, String runtime) {
    return topic + "|" + runtime;
  }
}

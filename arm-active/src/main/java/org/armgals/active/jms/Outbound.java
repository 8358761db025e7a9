package org.armgals.active.jms;

import java.util.Map;
import org.jspecify.annotations.Nullable;

/**
 * One message, or one event of a batch, waiting for the transport's sender thread: its topic, its
 * encoded value and its properties. Immutable.
 *
 * @param topic where it goes
 * @param route the stream it keeps its order and its sequence numbers in (topic and destination
 *     runtime, or node for answers); null: none (published events, look-ups, markers)
 * @param batchable whether it may share a message with the events before and after it on its route
 * @param value the encoded value (see {@link WireCodec#encodeValue})
 * @param properties its JMS properties
 * @param reliable whether it travels at least once (persistent, duplicate-checked, sent again until
 *     the broker has it)
 * @param corr the correlation number of the request it is, whose future fails if it is dropped; 0:
 *     not a request
 */
record Outbound(
    JmsTransport.Topic topic,
    @Nullable String route,
    boolean batchable,
    byte[] value,
    Map<String, Object> properties,
    boolean reliable,
    long corr) {

  /** Stops the sender thread. */
  static final Outbound STOP =
      new Outbound(JmsTransport.Topic.ENTITY, null, false, new byte[0], Map.of(), false, 0);

  /** What is not a request and travels at most once. */
  Outbound(
      JmsTransport.Topic topic,
      @Nullable String route,
      boolean batchable,
      byte[] value,
      Map<String, Object> properties) {
    this(topic, route, batchable, value, properties, false, 0);
  }

  /** The route of what goes to {@code runtime} (or a node, for answers) on {@code topic}. */
  static String route(JmsTransport.Topic topic, String runtime) {
    return topic + "|" + runtime;
  }
}

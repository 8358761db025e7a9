package org.armgals.active.jms;

import java.util.Map;
import java.util.Set;
import org.armgals.active.Event;
import org.armgals.active.Filter;

/**
 * The JMS message properties of the transport: routing ones (prefixed {@code arm_}, for the
 * transport's own selectors) and selector ones (for users' {@link Filter}s).
 */
final class WireProperties {
  private WireProperties() {}

  /** What a message carries: one of the {@code MSG_} values. */
  static final String MSG = "arm_msg";

  /** The destination runtime of an event or request. */
  static final String TO = "arm_to";

  /** The transport (node) that waits for an answer. */
  static final String NODE = "arm_node";

  /** The correlation number of a request, a look-up and their answers. */
  static final String CORR = "arm_corr";

  /** The number of events of a batch. */
  static final String COUNT = "arm_count";

  /** The name of a look-up. */
  static final String NAME = "arm_name";

  /** Why a request failed, in a failure answer. */
  static final String ERROR = "arm_error";

  /** The node (transport) that published an event, or that sent a message of a route. */
  static final String FROM = "arm_from";

  /** The sequence number of a route's message (its first event's, for a batch); from 1. */
  static final String RSEQ = "arm_rseq";

  /** Present (true) on the messages of at-least-once routes. */
  static final String ALO = "arm_alo";

  /** A subscription's swap marker: the subscription's id. */
  static final String MARKER = "arm_marker";

  static final String MSG_PUBLISH = "publish";
  static final String MSG_EVENT = "event";
  static final String MSG_BATCH = "batch";
  static final String MSG_REQUEST = "request";
  static final String MSG_ANSWER = "answer";
  static final String MSG_FAILURE = "failure";
  static final String MSG_LOOKUP = "lookup";

  /** Selector property: the event's type, its simple class name. */
  static final String KIND = "kind";

  /** Selector property: the sender's address as {@code runtime#id}, absent without a sender. */
  static final String SENDER = "sender";

  /** Selector property: the destination's address as {@code runtime#id}. */
  static final String DESTINATION = "destination";

  /** Selector property: the sending transport's sequence number of the event. */
  static final String SEQ = "seq";

  private static final Set<String> RESERVED = Set.of(KIND, SENDER, DESTINATION, SEQ);

  /** Checks an event's own selector properties: names free and well-formed, values JMS types. */
  static void checkUserProperties(Event event, Map<String, ?> properties) {
    Filter.ALL.matches(properties);
    for (String name : properties.keySet()) {
      if (RESERVED.contains(name)
          || name.startsWith("arm_")
          || name.startsWith("JMS")
          || !Character.isJavaIdentifierStart(name.charAt(0))
          || !name.chars().allMatch(Character::isJavaIdentifierPart)) {
        throw new IllegalArgumentException(
            "selector property '"
                + name
                + "' of "
                + event.getClass().getName()
                + " is not allowed: expected a Java identifier that starts with neither JMS nor"
                + " arm_ and is none of "
                + RESERVED);
      }
    }
  }

  /** A string as a selector literal: {@code 'it''s'}. */
  static String literal(String s) {
    return "'" + s.replace("'", "''") + "'";
  }
}

package org.armgals.active;

import java.util.Map;

/**
 * A content-based filter over an event's properties, written as a JMS message selector (paper §2.3,
 * §4.1; docs/architecture.md, runtime semantics 6): {@code kind = 'StateEvent' AND energy < 20}.
 *
 * <p>A filter means the same thing on both paths: locally, {@link #matches} evaluates the
 * expression with Apache ActiveMQ Artemis's own selector implementation; on a broker, {@link
 * #expression()} is handed to Artemis as the subscription's selector. Property values are {@link
 * String}s, {@link Boolean}s and the numbers {@link Byte}, {@link Short}, {@link Integer}, {@link
 * Long}, {@link Float} and {@link Double}, as in JMS message properties. A property that is absent
 * is SQL {@code NULL}: a comparison with it is unknown and the event does not match, as on a
 * broker.
 *
 * <p>Filters are immutable values (equal when their expressions are equal) and thread-safe.
 */
public interface Filter {

  /** The filter that accepts every event; its {@link #expression()} is empty. */
  Filter ALL = AcceptAll.INSTANCE;

  /**
   * Compiles a JMS message-selector expression. A blank expression is {@link #ALL}.
   *
   * @throws IllegalArgumentException the expression is not a valid selector; the message quotes it
   *     and says why
   */
  static Filter selector(String expression) {
    return SelectorFilter.compile(expression);
  }

  /**
   * The selector expression as given, for a broker subscription; empty for {@link #ALL} (JMS: no
   * selector).
   */
  String expression();

  /**
   * Whether an event with these properties passes the filter. An expression that cannot be
   * evaluated on these values (a string compared with a number) does not match, as on a broker.
   *
   * @throws IllegalArgumentException a value is not a String, Boolean, Byte, Short, Integer, Long,
   *     Float or Double (the message names the property)
   */
  boolean matches(Map<String, ?> properties);
}

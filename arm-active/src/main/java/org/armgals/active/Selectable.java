package org.armgals.active;

import java.util.Map;

/**
 * An event that declares properties for {@link Filter}s to select on, beside the ones every event
 * has ({@code kind}, {@code sender}, {@code destination}, {@code seq}). On a JMS transport they
 * travel as JMS message properties, so a broker-side selector sees the same values.
 *
 * <p>Values are Strings, Booleans, Bytes, Shorts, Integers, Longs, Floats or Doubles; names are JMS
 * identifiers that start with neither {@code JMS} nor {@code arm_}, and are none of the four names
 * above.
 */
public interface Selectable extends Event {

  /** The event's own selector properties; called once per send, on the sender's thread. */
  Map<String, ?> selectorProperties();
}

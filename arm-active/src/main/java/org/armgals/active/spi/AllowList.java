package org.armgals.active.spi;

import org.armgals.active.Event;

/**
 * The types a transport that serializes events may carry, the topic each event goes on, and which
 * travel at least once: a module that defines events (the kernel) fills it through this interface,
 * naming no transport. {@code org.armgals.active.jms.JmsTransport.Builder} is one.
 *
 * <p>Topics are named by their paths, the paper's: {@code arm/Entity} (what goes to objects, the
 * default), {@code arm/SMeta} (to structural meta-entities) and {@code arm/BMeta} (to behavioral
 * meta-entities).
 */
public interface AllowList {

  /**
   * Allows records and enums (events, requests, answers and the values in them), events on the
   * default topic {@code arm/Entity}.
   */
  AllowList allow(Class<?>... types);

  /**
   * Allows the event {@code type} on the topic {@code topic}.
   *
   * @throws IllegalArgumentException {@code topic} is not {@code arm/Entity}, {@code arm/SMeta} or
   *     {@code arm/BMeta}
   */
  AllowList allow(String topic, Class<? extends Event> type);

  /**
   * Sends {@code types} at least once, with duplicates suppressed, where the transport has such a
   * guarantee (the others go at most once).
   */
  AllowList atLeastOnce(Class<?>... types);
}

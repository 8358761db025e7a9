package org.armgals.kernel;

import java.util.Map;
import org.armgals.active.Address;
import org.armgals.active.Event;

/**
 * What a base-level entity tells its behavioral meta-entity (flows 1 and 2 of §3.1). Every
 * notification carries the entity's address and a sequence number, consecutive per entity over all
 * its notifications, from which the meta detects a lost one; the meta judges it with its filter
 * over {@link #properties()}.
 *
 * <p>Notifications are records of simple values (strings, numbers, booleans, addresses, lists and
 * maps of those) so that a codec can allow-list them when they cross runtimes.
 */
public sealed interface Notification extends Event
    permits StateEvent, ActionEvent, ThresholdEvent, FailureEvent, ReflectiveRequest {

  /** The entity that sent it. */
  Address entity();

  /** Its number in the entity's sequence of notifications, from 1. */
  long seq();

  /**
   * The entity's time at the step it tells of, in nanoseconds from its kernel's time source: the
   * base level's clock, which a meta uses for the damping of what it decides on this notification
   * ({@link org.armgals.kernel.spi.MetaContext#nanoTime()}), so that a meta in another runtime
   * decides in the base level's time (virtual time in a simulation) as one in the same runtime.
   */
  long nanoTime();

  /** Its kind for selectors: {@code state}, {@code action}, {@code threshold}, ... */
  String kind();

  /**
   * What a selector sees of it: {@code kind}, {@code entity} (the address as a string), {@code
   * seq}, and the properties of its kind.
   */
  Map<String, Object> properties();

  @Override
  default Address sender() {
    return entity();
  }
}

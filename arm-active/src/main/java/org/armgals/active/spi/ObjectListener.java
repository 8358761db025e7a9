package org.armgals.active.spi;

import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.OverflowPolicy;
import org.jspecify.annotations.Nullable;

/**
 * Hears what happens to one active object that the object's own code does not see: events its
 * buffer dropped, and failures while processing. This is where a behavioral meta-entity plugs in.
 *
 * <p>Threading: {@link #onDropped} runs on the thread that sent the event that overflowed the
 * buffer; {@link #onFailed} runs on the object's own thread. Implementations must be thread-safe,
 * quick and must not throw (what they throw goes to the runtime's error handler).
 */
public interface ObjectListener {

  /** A listener that does nothing. */
  ObjectListener NONE = new ObjectListener() {};

  /** The buffer of {@code object}, applying {@code policy}, dropped {@code event}. */
  default void onDropped(Address object, Event event, OverflowPolicy policy) {}

  /**
   * The processing of {@code event} by {@code object} threw {@code error}; {@code event} is {@code
   * null} when the failure happened outside an event (a reactive cycle).
   */
  default void onFailed(Address object, @Nullable Event event, Throwable error) {}
}

package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * Anything queued in an active object's bounded buffer (paper §4.1, class {@code Event}).
 *
 * <p>An event has a sender and a destination. While it waits in the receiver's buffer, {@link
 * #isProcessable()} tells whether it may be processed given the current state of the receiver's
 * servant; an event that is not processable stays queued and is asked again after the receiver's
 * state has changed (that is, after the receiver has processed another event).
 *
 * <p>Events that carry data are usually records implementing this interface and are handled by a
 * servant implementing {@link EventProcessor}; events that activate methods implement {@link
 * Callable}. Events should be immutable: the sender must not touch an event once sent.
 *
 * <p>Threading: {@link #isProcessable()} is called only by the receiving object, one call at a
 * time, never concurrently with the processing of another event by that object.
 */
public interface Event {

  /**
   * The object that sent this event.
   *
   * @return its address, or {@code null} if the event was sent from code that does not run inside
   *     an active object (a test, a {@code main} method)
   */
  @Nullable Address sender();

  /** The object this event is sent to. */
  Address destination();

  /**
   * Whether the receiver may process this event now. The default answers {@code true}; {@link
   * Callable} answers its guard.
   */
  default boolean isProcessable() {
    return true;
  }
}

package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * A node of an object's buffer, and the runtime's view of one queued event. Every event is queued
 * as exactly one envelope: method requests are their own envelopes (no extra allocation), data
 * events are wrapped.
 *
 * <p>Its link ({@link Link}) is written by producers and read by the consumer; the other fields are
 * written before the envelope is published by the enqueue and read only by the receiving object.
 */
abstract class Envelope extends Link implements Event {
  /** The sending object's address; null from outside any object. */
  @Nullable Address from;

  /** The receiving object; set when sent. */
  @Nullable Core<?> to;

  /**
   * A synchronous sender's send counter when sent, 0 from any other sender: orders a synchronous
   * instant deterministically (events of one asynchronous sender arrive in the order it sent them,
   * and the instant's order is stable).
   */
  long seq;

  /** The link of the receiver's private list of deferred (not yet processable) events. */
  @Nullable Envelope deferredNext;

  /** Binds the envelope to its route; false if it was already sent once. */
  final boolean bind(@Nullable Address sender, Core<?> receiver, long sequence) {
    if (to != null) {
      return false;
    }
    from = sender;
    to = receiver;
    seq = sequence;
    return true;
  }

  /** Whether it may be processed now by {@code servant}. Called on the receiver's thread. */
  abstract boolean processable(Object servant);

  /** Processes it on the receiver's thread; a thrown exception is a failure of this event. */
  abstract void process(Core<?> receiver) throws Exception;

  /** It will never be processed (dropped, object stopped): fail its future, if it has one. */
  void abandon(ActiveException cause) {}

  /** It failed while processing: fail its future, if it has one. */
  void failed(Throwable cause) {}

  /** Lets go of the payload once processed: the last envelope stays as the buffer's stub. */
  void clear() {}

  /** The event as users see it (listeners, error handler). */
  Event event() {
    return this;
  }

  /** Whether it bypasses the capacity check (replies the receiver asked for). */
  boolean privileged() {
    return false;
  }

  @Override
  public final @Nullable Address sender() {
    return from;
  }

  @Override
  public final Address destination() {
    Core<?> c = to;
    if (c == null) {
      throw new IllegalStateException("not sent yet: " + getClass().getName());
    }
    return c.address();
  }
}

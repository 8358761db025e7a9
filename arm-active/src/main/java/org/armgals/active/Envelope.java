package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * A node of an object's buffer, and the runtime's view of one queued event. Every event is queued
 * as exactly one envelope: method requests are their own envelopes (no extra allocation), data
 * events are wrapped.
 *
 * <p>Its link ({@link Link}) is written by producers and read by the consumer; the other fields are
 * written before the envelope is published by the enqueue and read only by the receiving object. It
 * is kept small (24 bytes for a one-way request): the sender allocates one per event and the
 * receiving core reads it from the sender's cache, so every line it spans costs both sides
 * (decision 0059). Hence no send counter (one sender's events reach a buffer in the order it sent
 * them, and a synchronous instant's sort is stable) and no link of its own for the deferred list.
 */
abstract class Envelope extends Link implements Event {
  /**
   * The sending object; null from outside any object. The object, not its address: an address is
   * made only when someone asks for it, and most senders are never asked (decision 0059).
   */
  @Nullable Core<?> from;

  /** Binds the envelope to its route; false if it was already sent once. */
  final boolean bind(@Nullable Core<?> sender, Core<?> receiver) {
    if (!claim(receiver)) {
      return false;
    }
    from = sender;
    return true;
  }

  /**
   * Takes {@code receiver} as the one object this envelope goes to; false if it was sent before. An
   * envelope the runtime makes for one send cannot be sent twice and keeps no receiver (a field
   * less in every one-way request); those a user makes ({@link ServantRequest}) remember it.
   */
  boolean claim(Core<?> receiver) {
    return true;
  }

  /** The object it was sent to, if it keeps it; null otherwise, and before it is sent. */
  @Nullable Core<?> receiver() {
    return null;
  }

  /**
   * Whether it may be processed now by {@code servant}; by default always (no guard). Called on the
   * receiver's thread.
   */
  boolean processable(Object servant) {
    return true;
  }

  /** Processes it on the receiver's thread; a thrown exception is a failure of this event. */
  abstract void process(Core<?> receiver) throws Exception;

  /** It will never be processed (dropped, object stopped): fail its future, if it has one. */
  void abandon(ActiveException cause) {}

  /** It failed while processing: fail its future, if it has one. */
  void failed(Throwable cause) {}

  /** Lets go of the payload once processed: the last envelope stays as the buffer's stub. */
  void clear() {}

  /**
   * The event as users see it (listeners, error handler), sent to {@code receiver}: the envelope
   * itself if it keeps its receiver, otherwise a view that names it.
   */
  Event event(Core<?> receiver) {
    return receiver() != null ? this : new Routed(sender(), receiver.address(), toString());
  }

  /** What a listener sees of an envelope that keeps no receiver. */
  private record Routed(@Nullable Address sender, Address destination, String request)
      implements Event {
    @Override
    public String toString() {
      return request + " to " + destination;
    }
  }

  /** Whether it bypasses the capacity check (replies the receiver asked for). */
  boolean privileged() {
    return false;
  }

  @Override
  public final @Nullable Address sender() {
    Core<?> f = from;
    return f == null ? null : f.address();
  }

  @Override
  public final Address destination() {
    Core<?> c = receiver();
    if (c == null) {
      throw new IllegalStateException("not sent yet: " + getClass().getName());
    }
    return c.address();
  }
}

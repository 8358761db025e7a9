package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * The fields of an active object that senders read or write on every send: its configuration and
 * its state (read), the buffer's tail (an atomic exchange) and its size (an atomic add). They come
 * last in the object's layout, after {@link SenderSidePadding}, away from {@link ReceiverSide}'s
 * fields, which the receiving object reads on every event. Sharing a line made both sides miss on
 * every event (decision 0078). See {@link Core}.
 */
abstract class SenderSide extends SenderSidePadding {
  /** The object's configuration: its mode, capacity and overflow policy. */
  final ObjectConfig config;

  /** {@link Core#SCHEDULED} and {@link Core#STOPPED}. */
  volatile int state;

  /** The buffer's last node; producers swap it. */
  volatile @Nullable Link tail;

  /** Events queued, reserved by producers; see {@link Core#queueDepth()}. */
  volatile int size;

  SenderSide(Object servant, RuntimeImpl runtime, long id, ObjectConfig config) {
    super(servant, runtime, id);
    this.config = config;
  }
}

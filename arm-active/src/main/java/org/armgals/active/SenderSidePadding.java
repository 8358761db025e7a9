package org.armgals.active;

import java.util.concurrent.ConcurrentLinkedQueue;
import org.jspecify.annotations.Nullable;

/**
 * At least 64 bytes between {@link SenderSide}'s fields and {@link Core}'s: filled first with the
 * fields that neither senders nor the receiving object touch on every event, the rest is padding.
 */
abstract class SenderSidePadding extends SenderSide {
  /** The object's number in its runtime. */
  final long id;

  /** The object's address, made on first use. */
  @Nullable Address address;

  /** Senders parked by the block policy; created on first use. */
  volatile @Nullable ConcurrentLinkedQueue<Thread> blocked;

  /** The future this object's thread waits on, for wait-for cycle detection. */
  volatile @Nullable ValueFuture<?> waitingFor;

  /** Synchronous mode only: what the clock's release fixed; null for asynchronous objects. */
  final Core.@Nullable Instant instant;

  /** The last of the object's deferred events (touched only when an event is deferred). */
  @Nullable Envelope deferredTail;

  // 28 bytes of fields above; 36 of padding complete the 64.
  @SuppressWarnings("unused")
  private long p1, p2, p3, p4;

  @SuppressWarnings("unused")
  private int p5;

  SenderSidePadding(long id, Core.@Nullable Instant instant) {
    this.id = id;
    this.instant = instant;
  }
}

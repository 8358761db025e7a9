package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * The fields between {@link SenderSide}'s and {@link Core}'s: those that neither the senders nor
 * the receiving object write on every event, then 24 bytes of padding, so that the senders' fields
 * and the receiver's are at least 48 bytes apart and share a cache line only for objects placed at
 * the one or two addresses in eight where they still do. An idle object costs at most 100 bytes in
 * all (decision 0045); padding to a whole line would cost 40 more.
 */
abstract class SenderSidePadding extends SenderSide {
  /** The object's number in its runtime. */
  final long id;

  /** The object's runtime. */
  final RuntimeImpl runtime;

  /** The object's configuration: its mode, capacity and overflow policy. */
  final ObjectConfig config;

  /** The object's address, made on first use. */
  @Nullable Address address;

  /**
   * What few objects need, made on first need: the blocked senders, the future waited for, the
   * deferred events, a synchronous object's instant, a drop-oldest object's buffer.
   */
  volatile Core.@Nullable Rare rare;

  @SuppressWarnings("unused")
  private long p1, p2, p3;

  SenderSidePadding(long id, RuntimeImpl runtime, ObjectConfig config) {
    this.id = id;
    this.runtime = runtime;
    this.config = config;
  }
}

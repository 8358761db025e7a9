package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * The fields of an active object that its own activation reads on every event it takes, and that no
 * sender reads or writes on an ordinary send. They come first in the object's layout (a
 * superclass's fields are laid out before its subclass's), after the header and the two links, so
 * that they share a cache line with the servant made just before the object (the usual order:
 * {@code spawn(new Servant())}), which the same activation writes: that sharing costs nothing.
 * {@link SenderSide}'s fields come last, after {@link SenderSidePadding} (decision 0078). See
 * {@link Core}.
 */
abstract class ReceiverSide extends RunQueue.Node {
  /** The object's servant. */
  final Object servant;

  /**
   * What few objects need, made on first need: the blocked senders, the future waited for, the
   * deferred events, a synchronous object's instant, a drop-oldest object's buffer. Senders read it
   * only for drop-oldest objects.
   */
  volatile Core.@Nullable Rare rare;

  /**
   * Set once the object is stopped, after {@link Core#STOPPED} is set in the senders' state: the
   * copy the activation reads between two events.
   */
  volatile boolean stopped;

  ReceiverSide(Object servant) {
    this.servant = servant;
  }
}

package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * The fields of an active object that senders write on every send: the buffer's tail (an atomic
 * exchange) and its size (an atomic add). They come first in the object's layout (a superclass's
 * fields are laid out before its subclass's), and {@link SenderSidePadding} keeps them away from
 * the receiving side's fields, which the object reads or writes on every event it takes: sharing a
 * line made both sides miss on every event (measured: counting ran at 9-18M events/s instead of
 * 20-23M). See {@link Core}.
 */
abstract class SenderSide extends RunQueue.Node {
  /** The buffer's last node; producers swap it. */
  volatile @Nullable Link tail;

  /** Events queued, reserved by producers; see {@link Core#queueDepth()}. */
  volatile int size;
}

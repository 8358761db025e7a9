package org.armgals.active;

/**
 * The consumer's end of a {@link RunQueue}, laid out first in the queue object: what the polling
 * worker reads and writes on every poll. The producers' end comes after {@link RunQueuePadding}.
 */
abstract class RunQueueConsumerSide {
  /** The node the queue holds when it holds no object. */
  final RunQueue.Stub stub = new RunQueue.Stub();

  /** The next node to take; written only by the worker holding {@link #polling}. */
  volatile RunQueue.Node first = stub;

  /** Held by the one worker polling at a time (a try-lock). */
  @SuppressWarnings("unused") // accessed through RunQueue's POLLING
  volatile boolean polling;
}

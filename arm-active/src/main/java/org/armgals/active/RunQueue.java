package org.armgals.active;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import org.jspecify.annotations.Nullable;

/**
 * The queue of objects with work, shared by a runtime's workers. The objects are the nodes (an
 * object is queued at most once, under its SCHEDULED bit), so queueing allocates nothing.
 *
 * <p>Producers are lock-free: one atomic exchange on {@link #last} (D. Vyukov's intrusive
 * multi-producer queue; its stub is pushed back when the queue runs dry, so a node leaves the queue
 * entirely when polled and can be queued again at once). The few workers take turns as the single
 * consumer through a try-lock; a worker that finds the lock taken polls again later.
 *
 * <p>The producers' end, {@link #last}, lies a cache line away from the consumer's ({@link
 * RunQueueConsumerSide}): a sender queueing objects on one core and a worker polling them on the
 * other then each write their own line, and the worker reads the producers' only when its own end
 * says the queue may be empty. Sharing one line, the two ends moved it between the cores twice per
 * object (decision 0081).
 */
final class RunQueue extends RunQueuePadding {
  private static final VarHandle LAST;
  private static final VarHandle NEXT;
  private static final VarHandle POLLING;

  static {
    try {
      MethodHandles.Lookup l = MethodHandles.lookup();
      LAST = l.findVarHandle(RunQueue.class, "last", Node.class);
      POLLING = l.findVarHandle(RunQueueConsumerSide.class, "polling", boolean.class);
      NEXT = l.findVarHandle(Node.class, "runNext", Node.class);
    } catch (ReflectiveOperationException e) {
      throw new ExceptionInInitializerError(e);
    }
  }

  /** A queueable node: {@link Core}, or the queue's stub. */
  abstract static class Node extends Link {
    @SuppressWarnings("unused") // accessed through NEXT
    private volatile @Nullable Node runNext;
  }

  /** The node the queue holds when it holds no object. */
  static final class Stub extends Node {}

  /** The producers' end. */
  @SuppressWarnings("unused") // accessed through LAST
  private volatile Node last = stub;

  void offer(Node n) {
    NEXT.setRelease(n, (Node) null);
    Node prev = (Node) LAST.getAndSet(this, n);
    NEXT.setRelease(prev, n);
  }

  /**
   * Whether the queue is empty. After a producer's exchange it answers false until a worker has
   * taken the object; it may also answer true while a polling worker still has objects ahead of the
   * stub, which that (running) worker takes on its next poll.
   */
  boolean isEmpty() {
    return first == stub && last == stub; // the consumer's own line first
  }

  /** The oldest queued object, or null if there is none (or another worker is polling). */
  @Nullable Core<?> poll() {
    if (isEmpty()) {
      return null;
    }
    if (!POLLING.compareAndSet(this, false, true)) {
      return null;
    }
    try {
      return (Core<?>) take();
    } finally {
      POLLING.setRelease(this, false);
    }
  }

  private @Nullable Node take() {
    Node f = first;
    Node next = (Node) NEXT.getAcquire(f);
    if (f == stub) {
      if (next == null) {
        return null;
      }
      first = next;
      f = next;
      next = (Node) NEXT.getAcquire(next);
    }
    if (next != null) {
      first = next;
      return taken(f);
    }
    if (f != last) {
      return null; // a producer is between its exchange and its link: try again later
    }
    offer(stub);
    next = (Node) NEXT.getAcquire(f);
    if (next != null) {
      first = next;
      return taken(f);
    }
    return null;
  }

  /** The node after {@code n} in the queue, or null: for tests. */
  static @Nullable Node successorOf(Node n) {
    return (Node) NEXT.getAcquire(n);
  }

  /**
   * A node leaving the queue forgets its successor (no producer links to it any more: it is not the
   * last node). Otherwise an idle object would keep every object polled after it reachable, a chain
   * of stopped objects that the collector could not free while the first one lives.
   */
  private static Node taken(Node n) {
    NEXT.setRelease(n, (Node) null);
    return n;
  }
}

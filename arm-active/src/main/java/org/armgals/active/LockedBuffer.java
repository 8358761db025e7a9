package org.armgals.active;

import java.util.ArrayDeque;
import java.util.Iterator;
import java.util.List;
import java.util.concurrent.locks.ReentrantLock;
import org.jspecify.annotations.Nullable;

/**
 * The buffer of an object whose overflow policy is drop-oldest: a deque under a lock, since a
 * producer must be able to remove the oldest event while the object runs. Events the object found
 * not processable stay in place at the front ({@link #seen} of them), so the oldest event is always
 * the first, processable or not. Guards are evaluated under the lock; they must be cheap.
 */
final class LockedBuffer {
  private final ReentrantLock lock = new ReentrantLock();
  private final ArrayDeque<Envelope> queue = new ArrayDeque<>(4);

  /** The first {@code seen} events were found not processable in the current state. */
  private int seen;

  /** Synchronous mode: how many of the first events belong to the released instant. */
  private int atRelease;

  private volatile int count;

  int size() {
    return count;
  }

  /**
   * Queues {@code e}; if the buffer was full, removes and returns the oldest event that is not a
   * reply. Replies are never dropped and always queued, even beyond the capacity; while queued they
   * take a place like any event.
   */
  @Nullable Envelope offer(Envelope e, int capacity) {
    lock.lock();
    try {
      Envelope dropped = null;
      if (!e.privileged() && queue.size() >= capacity) {
        int i = 0;
        for (Iterator<Envelope> it = queue.iterator(); it.hasNext(); i++) {
          Envelope old = it.next();
          if (!old.privileged()) {
            it.remove();
            dropped = old;
            if (i < seen) {
              seen--;
            }
            if (i < atRelease) {
              atRelease--;
            }
            break;
          }
        }
      }
      queue.addLast(e);
      count = queue.size();
      return dropped;
    } finally {
      lock.unlock();
    }
  }

  /** Whether events arrived that the object has not looked at yet. */
  boolean hasUnseen() {
    lock.lock();
    try {
      return queue.size() > seen;
    } finally {
      lock.unlock();
    }
  }

  /** Removes and returns the oldest processable event (rescanning all if the state changed). */
  @Nullable Envelope takeProcessable(Core<?> core, boolean stateChanged) {
    lock.lock();
    try {
      int start = stateChanged ? 0 : seen;
      int i = 0;
      for (Iterator<Envelope> it = queue.iterator(); it.hasNext(); i++) {
        Envelope e = it.next();
        if (i >= start && core.processableSafely(e)) {
          it.remove();
          seen = i;
          count = queue.size();
          return e;
        }
      }
      seen = queue.size();
      return null;
    } finally {
      lock.unlock();
    }
  }

  /** Synchronous mode, phase 1 of a release. */
  void markRelease() {
    lock.lock();
    try {
      atRelease = queue.size();
    } finally {
      lock.unlock();
    }
  }

  /** Synchronous mode: removes the events of the released instant into {@code batch}. */
  void takeReleased(List<Envelope> batch) {
    lock.lock();
    try {
      for (int i = 0; i < atRelease; i++) {
        batch.add(queue.pollFirst());
      }
      atRelease = 0;
      seen = 0;
      count = queue.size();
    } finally {
      lock.unlock();
    }
  }

  /** Synchronous mode: what an instant could not process goes back in front, in order. */
  void putBack(List<Envelope> pending) {
    lock.lock();
    try {
      for (int i = pending.size() - 1; i >= 0; i--) {
        queue.addFirst(pending.get(i));
      }
      seen = pending.size();
      count = queue.size();
    } finally {
      lock.unlock();
    }
  }

  /** Removes everything (the object stopped). */
  void drainTo(List<Envelope> all) {
    lock.lock();
    try {
      all.addAll(queue);
      queue.clear();
      seen = 0;
      atRelease = 0;
      count = 0;
    } finally {
      lock.unlock();
    }
  }
}

package org.armgals.bench.savina.yardstick;

import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;

/**
 * An actor as one writes it by hand on a {@link ForkJoinPool}: a state, a {@link
 * ConcurrentLinkedQueue} of messages (functions of the state), and one atomic "scheduled" flag so
 * that at most one pool task runs the actor at a time. That task processes at most {@value #BATCH}
 * messages, clears the flag and submits itself again if messages are left. Written plainly, not
 * tuned: it is the yardstick a runtime is compared with.
 *
 * <p>Threading: {@link #send} may be called from any thread. Messages run one at a time, in the
 * order of their sends from any one thread; setting and clearing the flag orders each batch after
 * the previous one, so the state needs no locks. A message that throws is lost, the pool's
 * uncaught-exception handler hears of it, and the actor goes on with the next message.
 *
 * @param <T> the state's type
 */
final class Actor<T> implements Runnable {
  /** The most messages one pool task processes before it lets other actors run. */
  static final int BATCH = 64;

  private final ForkJoinPool pool;
  private final T state;
  private final ConcurrentLinkedQueue<Consumer<? super T>> mailbox = new ConcurrentLinkedQueue<>();
  private final AtomicBoolean scheduled = new AtomicBoolean();

  Actor(ForkJoinPool pool, T state) {
    this.pool = pool;
    this.state = state;
  }

  /** Queues {@code message} and, unless the actor is already scheduled, schedules it. */
  void send(Consumer<? super T> message) {
    mailbox.offer(message);
    if (scheduled.compareAndSet(false, true)) {
      pool.execute(this);
    }
  }

  /** Processes one batch; called by the pool only. */
  @Override
  public void run() {
    try {
      for (int i = 0; i < BATCH; i++) {
        Consumer<? super T> message = mailbox.poll();
        if (message == null) {
          break;
        }
        message.accept(state);
      }
    } finally {
      scheduled.set(false);
      // A send that found the flag still set has left its message for this check to see.
      if (!mailbox.isEmpty() && scheduled.compareAndSet(false, true)) {
        pool.execute(this);
      }
    }
  }
}

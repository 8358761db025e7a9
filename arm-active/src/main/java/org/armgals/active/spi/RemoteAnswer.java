package org.armgals.active.spi;

import org.armgals.active.ActiveException;
import org.armgals.active.FutureValue;
import org.armgals.active.TimeSource;
import org.jspecify.annotations.Nullable;

/**
 * The future of a request that a transport sends to another runtime: the caller holds it as a
 * {@link FutureValue}, and the transport completes it when the answer comes back. Made by {@link
 * FutureValue#remote}; it waits by necessity as every future of the runtime does, but its waiters
 * park at once (an answer that crosses a broker takes far longer than a spin) and read their
 * timeouts on the transport's {@link TimeSource}.
 *
 * <p>Thread-safe: the first of {@link #complete}, {@link #fail} and {@link #abandon} wins; later
 * ones do nothing.
 */
public interface RemoteAnswer<T extends @Nullable Object> extends FutureValue<T> {

  /** Completes the future with the answer's value. */
  void complete(T value);

  /** Fails the future: the servant threw {@code cause}. */
  void fail(Throwable cause);

  /**
   * Fails the future: the request never ran or its answer will not come ({@code cause} says why).
   */
  void abandon(ActiveException cause);

  /** Whether the future is completed; unlike {@link #isDone}, never a reason to receive. */
  boolean completed();

  /**
   * Who receives a transport's answers, so that a waiter can receive its own on its own thread
   * (decision 0032) instead of waking a receiving thread.
   */
  interface Receiver {
    /**
     * Receives answers on the calling thread, its future's and any other, until {@code future} is
     * completed or {@code deadline} (on the transport's time, if {@code timed}) has passed.
     *
     * @return true if the future may be completed or the time run out: the waiter looks again;
     *     false if the waiter should park, another thread receiving for it (the lead is taken, this
     *     thread may not lead, or receiving stopped: the transport closed, the connection failed,
     *     the thread was interrupted and its flag is set again)
     */
    boolean lead(RemoteAnswer<?> future, boolean timed, long deadline);

    /** The future is looked at without waiting: some thread must be receiving. */
    void observe();
  }
}

package org.armgals.active;

import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import org.jspecify.annotations.Nullable;

/**
 * The future of a synchronous (reactive) object: active wait (paper §5.2). The receiver's
 * completion is not written here directly; it is queued to the owner as a {@link
 * Requests.FutureReply} and takes effect when the owner processes it at one of its releases, when
 * the replying object runs on the same manual clock, the instant at which the value appears depends
 * only on instants, never on thread timing; an asynchronous replier answers whenever it runs, and
 * the value appears at the first release after that.
 *
 * <p>All reads and the arrival happen on the owner's thread (its instants are sequential).
 */
final class SyncFuture<T extends @Nullable Object>
    implements ReplyFuture<T>, SynchronousFutureValue<T> {
  private final Core<?> owner;
  private final Address completer;
  private final long requestId;

  private boolean arrived;
  private boolean abandoned;
  private @Nullable Object value;
  private @Nullable Throwable failure;
  private @Nullable CompletableFuture<T> stage;

  SyncFuture(Core<?> owner, Address completer, long requestId) {
    this.owner = owner;
    this.completer = completer;
    this.requestId = requestId;
  }

  Address completer() {
    return completer;
  }

  long requestId() {
    return requestId;
  }

  // receiver side: queue the reply to the owner
  @Override
  public void complete(T v) {
    deliver(v, null, false);
  }

  @Override
  public void fail(Throwable cause) {
    deliver(null, cause, false);
  }

  @Override
  public void abandon(ActiveException cause) {
    deliver(null, cause, true);
  }

  private void deliver(@Nullable Object v, @Nullable Throwable cause, boolean neverRan) {
    try {
      owner.post(new Requests.FutureReply(this, v, cause, neverRan));
    } catch (ObjectStoppedException stopped) {
      // The owner is gone; nobody can read this future any more.
      owner.runtime.countDropped();
    }
  }

  // owner side
  synchronized void arrive(@Nullable Object v, @Nullable Throwable cause, boolean neverRan) {
    value = v;
    failure = cause;
    abandoned = neverRan;
    arrived = true;
    CompletableFuture<T> s = stage;
    if (s != null) {
      completeStage(s);
    }
  }

  @SuppressWarnings("unchecked")
  private void completeStage(CompletableFuture<T> s) {
    Throwable f = failure;
    if (f != null) {
      s.completeExceptionally(f);
    } else {
      s.complete((T) value);
    }
  }

  @Override
  public synchronized boolean isDone() {
    return arrived;
  }

  @Override
  public void touch() {
    getValue();
  }

  @Override
  public void touch(Duration timeout) {
    getValue(timeout);
  }

  @Override
  @SuppressWarnings("unchecked")
  public synchronized T getValue() {
    if (!arrived) {
      throw new FutureNotAvailableException(completer.toString(), owner.currentInstant());
    }
    Throwable f = failure;
    if (f != null) {
      if (abandoned && f instanceof ActiveException e) {
        throw e;
      }
      throw new RequestFailedException(completer.toString(), f);
    }
    return (T) value;
  }

  /** Never waits: the same as {@link #getValue()}, once the timeout is checked. */
  @Override
  public T getValue(Duration timeout) {
    java.util.Objects.requireNonNull(timeout, "timeout");
    if (timeout.isNegative()) {
      throw new IllegalArgumentException("timeout must be >= 0, was " + timeout);
    }
    return getValue();
  }

  @Override
  public synchronized CompletionStage<T> toCompletionStage() {
    CompletableFuture<T> s = stage;
    if (s == null) {
      s = new CompletableFuture<>();
      stage = s;
      if (arrived) {
        completeStage(s);
      }
    }
    return s.minimalCompletionStage();
  }

  @Override
  public synchronized String toString() {
    return "SynchronousFutureValue[" + completer + ", " + (arrived ? "available" : "pending") + "]";
  }
}

package org.armgals.active;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.locks.LockSupport;
import org.armgals.active.spi.RemoteAnswer;
import org.jspecify.annotations.Nullable;

/**
 * The future of the asynchronous world: wait by necessity. A waiter first spins briefly (most
 * replies between objects come within microseconds; not for an answer that crosses a broker, see
 * {@link #remote}), then checks that waiting would not close a wait-for cycle, then parks. A worker
 * thread that parks tells its dispatcher, which starts another worker so that only the waiting
 * object waits.
 *
 * <p>{@link #result} goes once from {@code null} to the value ({@link #NIL} for null) or a {@link
 * Failure}; the completing write happens-before every read that sees it.
 */
final class ValueFuture<T extends @Nullable Object> implements ReplyFuture<T>, RemoteAnswer<T> {
  private static final Object NIL = new Object();

  /**
   * How long a waiter spins before it parks. Longer than a parked worker takes to wake (tens of
   * microseconds on a virtual machine): a waiter that parks first makes the replier park too on the
   * next request, and a request/reply loop then pays two wake-ups per round trip (measured: 20k
   * round trips/s instead of 0.5-2M/s).
   */
  private static final long SPIN_NANOS = 200_000;

  private static final int MAX_CHAIN = 10_000;
  private static final VarHandle RESULT;
  private static final VarHandle WAITERS;
  private static final VarHandle STAGE;

  static {
    try {
      MethodHandles.Lookup l = MethodHandles.lookup();
      RESULT = l.findVarHandle(ValueFuture.class, "result", Object.class);
      WAITERS = l.findVarHandle(ValueFuture.class, "waiters", Waiter.class);
      STAGE = l.findVarHandle(ValueFuture.class, "stage", CompletableFuture.class);
    } catch (ReflectiveOperationException e) {
      throw new ExceptionInInitializerError(e);
    }
  }

  /** A failed completion: the servant threw ({@code servant}) or the request never ran. */
  private record Failure(Throwable cause, boolean servant) {}

  private static final class Waiter {
    volatile @Nullable Thread thread;
    final @Nullable Waiter next;

    Waiter(Thread thread, @Nullable Waiter next) {
      this.thread = thread;
      this.next = next;
    }
  }

  /**
   * The object that will complete this future; null for an already completed one and for one that a
   * transport completes.
   */
  private final @Nullable Core<?> completer;

  /**
   * Where the answer of a future a transport completes comes from ({@code from}, for messages), the
   * time its waiters' timeouts are read on, and who receives it (null: whoever completes it).
   */
  private record Remote(String from, TimeSource time, RemoteAnswer.@Nullable Receiver receiver) {}

  /** Null unless a transport completes this future; its waiters then park at once. */
  private final @Nullable Remote remote;

  private volatile @Nullable Object result;
  private volatile @Nullable Waiter waiters;
  private volatile @Nullable CompletableFuture<T> stage;

  ValueFuture(@Nullable Core<?> completer) {
    this(completer, null);
  }

  private ValueFuture(@Nullable Core<?> completer, @Nullable Remote remote) {
    this.completer = completer;
    this.remote = remote;
  }

  /**
   * A future that a transport completes when the answer comes back from another runtime. Its
   * waiters park at once: such an answer takes a broker round trip, far longer than the spin, and a
   * waiter spinning for it only takes a core from the threads that carry the request and its answer
   * (measured on 2 cores: p50 of a round trip over netty 470-560 µs spinning, 235-370 µs parking).
   * Timeouts of {@link #getValue(Duration)} are read from {@code time}. A waiter receives the
   * answer itself through {@code receiver} when it can (decision 0032); a null receiver leaves it
   * to whoever completes the future. {@code from} names where the answer comes from in failures.
   */
  static <T extends @Nullable Object> ValueFuture<T> remote(
      String from, TimeSource time, RemoteAnswer.@Nullable Receiver receiver) {
    return new ValueFuture<>(
        null,
        new Remote(
            java.util.Objects.requireNonNull(from, "from"),
            java.util.Objects.requireNonNull(time, "time"),
            receiver));
  }

  static <T extends @Nullable Object> ValueFuture<T> completed(T value) {
    ValueFuture<T> f = new ValueFuture<>(null);
    f.complete(value);
    return f;
  }

  static <T extends @Nullable Object> ValueFuture<T> failed(Throwable failure) {
    ValueFuture<T> f = new ValueFuture<>(null);
    f.fail(failure);
    return f;
  }

  // ------------------------------------------------------------------ completion

  @Override
  public void complete(T value) {
    finish(value == null ? NIL : value);
  }

  @Override
  public void fail(Throwable cause) {
    finish(new Failure(cause, true));
  }

  @Override
  public void abandon(ActiveException cause) {
    finish(new Failure(cause, false));
  }

  private void finish(Object r) {
    if (!RESULT.compareAndSet(this, null, r)) {
      return;
    }
    for (Waiter w = (Waiter) WAITERS.getAndSet(this, null); w != null; w = w.next) {
      Thread t = w.thread;
      if (t != null) {
        LockSupport.unpark(t);
      }
    }
    CompletableFuture<T> s = stage;
    if (s != null) {
      completeStage(s, r);
    }
  }

  @SuppressWarnings("unchecked")
  private static <T extends @Nullable Object> void completeStage(CompletableFuture<T> s, Object r) {
    if (r instanceof Failure f) {
      s.completeExceptionally(f.cause());
    } else {
      s.complete(r == NIL ? null : (T) r);
    }
  }

  // ------------------------------------------------------------------ reading

  @Override
  public boolean isDone() {
    if (result != null) {
      return true;
    }
    Remote rm = remote;
    if (rm != null && rm.receiver() != null) {
      rm.receiver().observe();
    }
    return result != null;
  }

  @Override
  public boolean completed() {
    return result != null;
  }

  @Override
  public void touch() {
    report(await(-1));
  }

  @Override
  public void touch(Duration timeout) {
    report(await(nanos(timeout)));
  }

  @Override
  public T getValue() {
    return report(await(-1));
  }

  @Override
  public T getValue(Duration timeout) {
    return report(await(nanos(timeout)));
  }

  @Override
  public CompletionStage<T> toCompletionStage() {
    CompletableFuture<T> s = stage;
    if (s == null) {
      CompletableFuture<T> fresh = new CompletableFuture<>();
      s = STAGE.compareAndSet(this, null, fresh) ? fresh : stage;
      Object r = result;
      if (r != null && s != null) {
        completeStage(s, r);
      }
    }
    Remote rm = remote;
    if (rm != null && rm.receiver() != null && result == null) {
      rm.receiver().observe();
    }
    return java.util.Objects.requireNonNull(s).minimalCompletionStage();
  }

  private static long nanos(Duration timeout) {
    java.util.Objects.requireNonNull(timeout, "timeout");
    if (timeout.isNegative()) {
      throw new IllegalArgumentException("timeout must be >= 0, was " + timeout);
    }
    return timeout.toNanos();
  }

  private String completerName() {
    Core<?> c = completer;
    Remote rm = remote;
    return c != null ? c.address().toString() : rm != null ? rm.from() : "a completed future";
  }

  @SuppressWarnings("unchecked")
  private T report(Object r) {
    if (r instanceof Failure f) {
      if (!f.servant() && f.cause() instanceof ActiveException e) {
        throw e; // never ran: ObjectStoppedException or BufferFullException, as documented
      }
      throw new RequestFailedException(completerName(), f.cause());
    }
    return r == NIL ? (T) null : (T) r;
  }

  /** Waits by necessity; {@code timeoutNanos < 0} waits without limit. */
  private Object await(long timeoutNanos) {
    Object r = result;
    if (r != null) {
      return r;
    }
    Remote rm = remote;
    TimeSource time =
        completer != null
            ? completer.runtime.timeSource()
            : rm != null ? rm.time() : TimeSource.system();
    if (rm == null && (r = spin(time)) != null) {
      return r;
    }
    Core<?> me = Core.current();
    if (me != null) {
      if (me.mode() == Mode.SYNCHRONOUS) {
        throw new IllegalStateException(
            "synchronous object "
                + me.address()
                + " would block its cycle waiting for "
                + completerName()
                + "; reactive objects use the SynchronousFuture that call() gives them");
      }
      me.returnTaken();
      me.waitingFor(this);
      List<Address> cycle = findCycle(me);
      if (cycle != null) {
        me.waitingFor(null);
        throw new WaitCycleException(cycle);
      }
    }
    boolean timed = timeoutNanos >= 0;
    long deadline = timed ? time.nanoTime() + timeoutNanos : 0;
    Thread self = Thread.currentThread();
    Waiter w = push(self);
    RemoteAnswer.Receiver receiving = rm == null ? null : rm.receiver();
    Dispatcher.beforeBlock();
    try {
      while ((r = result) == null) {
        long remaining = timed ? deadline - time.nanoTime() : 1;
        if (remaining <= 0) {
          throw new FutureTimeoutException(completerName(), Duration.ofNanos(timeoutNanos));
        }
        if (receiving != null && receiving.lead(this, timed, deadline)) {
          continue;
        }
        if (timed) {
          LockSupport.parkNanos(this, remaining);
        } else {
          LockSupport.park(this);
        }
        if (Thread.interrupted()) {
          self.interrupt();
          if ((r = result) != null) {
            return r;
          }
          throw new FutureInterruptedException(
              completerName(), new InterruptedException("wait by necessity interrupted"));
        }
      }
      return r;
    } finally {
      w.thread = null;
      Dispatcher.afterBlock();
      if (me != null) {
        me.waitingFor(null);
      }
    }
  }

  private @Nullable Object spin(TimeSource time) {
    long spinEnd = time.nanoTime() + SPIN_NANOS;
    for (int i = 1; ; i++) {
      Thread.onSpinWait();
      Object r = result;
      if (r != null) {
        return r;
      }
      if ((i & 31) == 0 && time.nanoTime() >= spinEnd) {
        return null;
      }
    }
  }

  private Waiter push(Thread t) {
    for (; ; ) {
      Waiter head = waiters;
      Waiter w = new Waiter(t, head);
      if (WAITERS.compareAndSet(this, head, w)) {
        return w;
      }
    }
  }

  /**
   * Follows the wait-for chain from this future: its completer, the future that one waits on, that
   * one's completer, and so on. A chain back to {@code me} is a cycle; every object on it is parked
   * waiting for the next one, so it can never resolve by itself.
   */
  private @Nullable List<Address> findCycle(Core<?> me) {
    List<Address> path = new ArrayList<>();
    path.add(me.address());
    ValueFuture<?> f = this;
    for (int steps = 0; steps < MAX_CHAIN; steps++) {
      Core<?> c = f.completer;
      if (c == null) {
        return null;
      }
      path.add(c.address());
      if (c == me) {
        return path;
      }
      ValueFuture<?> next = c.waitingFor();
      if (next == null || next.result != null) {
        return null;
      }
      f = next;
    }
    return null;
  }

  @Override
  public String toString() {
    Object r = result;
    String s = r == null ? "pending" : r instanceof Failure f ? "failed: " + f.cause() : "done";
    return "FutureValue[" + completerName() + ", " + s + "]";
  }
}

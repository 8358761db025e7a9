package org.armgals.active;

import java.util.function.BiConsumer;
import org.jspecify.annotations.Nullable;

/** The envelopes the runtime makes itself: lambda requests, wrapped events, future replies. */
final class Requests {
  private Requests() {}

  /**
   * {@link ActiveRef#ask} on an object of this runtime: a guarded synchronized request that hands
   * the data request to the servant's {@link EventProcessor#answer}.
   */
  @SuppressWarnings("unchecked")
  static <R extends @Nullable Object> FutureValue<R> ask(ActiveRef<?> ref, Request<R> request) {
    java.util.Objects.requireNonNull(request, "request");
    if (!ref.address().equals(request.destination())) {
      throw new IllegalArgumentException(
          "request "
              + request
              + " is addressed to "
              + request.destination()
              + ", not "
              + ref.address());
    }
    return ((ActiveRef<Object>) ref)
        .callWhen(
            s -> processor(s, request).isProcessable(request),
            s -> (R) processor(s, request).answer(request));
  }

  /**
   * {@link #ask(ActiveRef, Request)} for a request from another runtime: its outcome goes to {@code
   * answer}, on the thread that completes it, instead of to a future that the caller would have to
   * subscribe to after the request is queued (by then a fast servant may have answered, and its
   * answer would wait for the subscription).
   */
  @SuppressWarnings("unchecked")
  static <R extends @Nullable Object> void ask(
      Core<?> core,
      Request<R> request,
      BiConsumer<? super @Nullable R, ? super @Nullable Throwable> answer) {
    java.util.Objects.requireNonNull(request, "request");
    java.util.Objects.requireNonNull(answer, "answer");
    if (!core.address().equals(request.destination())) {
      throw new IllegalArgumentException(
          "request " + request + " is addressed to " + request.destination() + ", not " + core);
    }
    ((Core<Object>) core)
        .request(
            s -> (R) processor(s, request).answer(request),
            s -> processor(s, request).isProcessable(request),
            new Answer<>(answer));
  }

  /** A {@link Reply} that hands the outcome to a callback. */
  private record Answer<R extends @Nullable Object>(
      BiConsumer<? super @Nullable R, ? super @Nullable Throwable> then) implements Reply<R> {
    @Override
    public void complete(R value) {
      then.accept(value, null);
    }

    @Override
    public void fail(Throwable cause) {
      then.accept(null, cause);
    }

    @Override
    public void abandon(ActiveException cause) {
      then.accept(null, cause);
    }
  }

  private static EventProcessor processor(Object servant, Request<?> request) {
    if (servant instanceof EventProcessor p) {
      return p;
    }
    throw new UnsupportedOperationException(
        servant.getClass().getName()
            + " is not an EventProcessor, so it cannot answer the request "
            + request);
  }

  /** Whether a lambda request's guard (none: always) holds for {@code servant}. */
  @SuppressWarnings("unchecked")
  private static <S> boolean holds(@Nullable Guard<? super S> guard, Object servant) {
    return guard == null || guard.test((S) servant);
  }

  /** A one-way request from {@link ActiveRef#send(ServantAction)}: no guard, always processable. */
  static sealed class Action<S> extends Envelope permits GuardedAction {
    private @Nullable ServantAction<? super S> action;

    Action(ServantAction<? super S> action) {
      this.action = action;
    }

    @Override
    @SuppressWarnings("unchecked")
    final void process(Core<?> receiver) throws Exception {
      ServantAction<? super S> a = action;
      if (a != null) {
        a.run((S) receiver.servant());
      }
    }

    @Override
    void clear() {
      action = null;
    }

    @Override
    public String toString() {
      return "OneWayRequest[from " + sender() + "]";
    }
  }

  /**
   * A guarded one-way request from {@link ActiveRef#sendWhen}; a class of its own so that the
   * unguarded one, by far the most sent, carries no guard field.
   */
  static final class GuardedAction<S> extends Action<S> {
    private @Nullable Guard<? super S> guard;

    GuardedAction(ServantAction<? super S> action, Guard<? super S> guard) {
      super(action);
      this.guard = guard;
    }

    @Override
    boolean processable(Object servant) {
      return holds(guard, servant);
    }

    @Override
    void clear() {
      super.clear();
      guard = null;
    }

    @Override
    public String toString() {
      return "OneWayRequest[from " + sender() + ", guarded]";
    }
  }

  /** A synchronized request from {@link ActiveRef#call(ServantFunction)} or {@code signal}. */
  static final class Function<S, R extends @Nullable Object> extends Envelope {
    private @Nullable ServantFunction<? super S, R> function;
    private @Nullable Guard<? super S> guard;
    private @Nullable Reply<R> reply;

    Function(ServantFunction<? super S, R> function, @Nullable Guard<? super S> guard, Reply<R> r) {
      this.function = function;
      this.guard = guard;
      this.reply = r;
    }

    @Override
    boolean processable(Object servant) {
      return holds(guard, servant);
    }

    @Override
    @SuppressWarnings("unchecked")
    void process(Core<?> receiver) throws Exception {
      ServantFunction<? super S, R> f = function;
      if (f == null) {
        throw new IllegalStateException("request processed twice");
      }
      R value = f.apply((S) receiver.servant());
      Reply<R> r = reply;
      if (r != null) {
        r.complete(value);
      }
    }

    @Override
    void abandon(ActiveException cause) {
      Reply<R> r = reply;
      if (r != null) {
        r.abandon(cause);
      }
    }

    @Override
    void failed(Throwable cause) {
      Reply<R> r = reply;
      if (r != null) {
        r.fail(cause);
      }
    }

    @Override
    void clear() {
      function = null;
      guard = null;
      reply = null;
    }

    @Override
    public String toString() {
      return "SynchronizedRequest[from " + sender() + "]";
    }
  }

  /** A data event, or a user {@link Callable} that is not one of the runtime's request classes. */
  static final class Wrapped extends Envelope {
    /** The event; null once processed, so that the buffer's stub does not keep it alive. */
    private @Nullable Event event;

    private boolean bound;

    Wrapped(Event event) {
      this.event = event;
    }

    @Override
    boolean processable(Object servant) {
      Event ev = event();
      if (ev instanceof Callable<?, ?> c) {
        bindServant(c, servant);
        return c.isProcessable();
      }
      if (servant instanceof EventProcessor p) {
        return p.isProcessable(ev);
      }
      return ev.isProcessable();
    }

    @Override
    void process(Core<?> receiver) throws Exception {
      Object servant = receiver.servant();
      Event ev = event();
      if (ev instanceof Callable<?, ?> c) {
        bindServant(c, servant);
        c.apply();
      } else if (servant instanceof EventProcessor p) {
        p.process(ev);
      } else {
        throw new IllegalStateException(
            "servant "
                + servant.getClass().getName()
                + " of "
                + receiver.address()
                + " takes no data events (it does not implement EventProcessor); got "
                + ev);
      }
    }

    @SuppressWarnings({"unchecked", "rawtypes"})
    private void bindServant(Callable c, Object servant) {
      if (!bound) {
        c.setServant(servant);
        bound = true;
      }
    }

    @Override
    void clear() {
      event = null;
    }

    @Override
    Event event(Core<?> receiver) {
      return event();
    }

    private Event event() {
      Event ev = event;
      if (ev == null) {
        throw new IllegalStateException("a processed event is not kept");
      }
      return ev;
    }

    @Override
    public String toString() {
      Event ev = event;
      return ev == null ? "processed event" : ev.toString();
    }
  }

  /** The reply to a synchronous object's request, taken at one of its releases. */
  static final class FutureReply extends Envelope {
    private final SyncFuture<?> future;
    private final @Nullable Object value;
    private final @Nullable Throwable failure;
    private final boolean neverRan;

    FutureReply(
        SyncFuture<?> future,
        @Nullable Object value,
        @Nullable Throwable failure,
        boolean neverRan) {
      this.future = future;
      this.value = value;
      this.failure = failure;
      this.neverRan = neverRan;
    }

    @Override
    void process(Core<?> receiver) throws Exception {
      future.arrive(value, failure, neverRan);
      if (receiver.servant() instanceof EventProcessor p) {
        p.process(event(receiver));
      }
    }

    @Override
    boolean privileged() {
      return true;
    }

    @Override
    Event event(Core<?> receiver) {
      return new FutureEvent(
          future.completer(), receiver.address(), future.requestId(), value, failure);
    }

    @Override
    public String toString() {
      return "FutureReply[request " + future.requestId() + " from " + future.completer() + "]";
    }
  }
}

package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * A typed reference to an active object, the way to send it events and requests. References are
 * cheap, thread-safe and may be shared freely.
 *
 * <p><b>One-way</b> ({@link #send}) requests return at once. <b>Synchronized</b> requests ({@link
 * #call}, {@link #signal}) return a future that waits by necessity. Called from inside a
 * synchronous (reactive) object they return a {@link SynchronousFutureValue} / {@link
 * SynchronousFuture} instead, which never waits (paper §5.2).
 *
 * <p>Ordering: the events one sender sends to one object are processed in the order they were sent,
 * among those that are processable (a guarded event may be overtaken by later processable ones; it
 * runs once its guard holds).
 *
 * <p>Errors: every send method throws {@link ObjectStoppedException} if the object is stopped,
 * {@link BufferFullException} if its buffer is full and its policy rejects (or blocks too long), an
 * {@link ActiveException} if the sender is interrupted while blocked by a full buffer (its
 * interrupt status is kept), and {@link NullPointerException} naming a null argument.
 *
 * @param <S> the type of the object's servant
 */
public interface ActiveRef<S> {

  /** The object's location-transparent address. */
  Address address();

  /**
   * Queues an event: a data event for a servant that is an {@link EventProcessor}, or a method
   * request ({@link MethodRequest}, {@link SynchronizedMethodRequest}, or any {@link Callable}).
   *
   * @throws IllegalArgumentException the event's destination is not this object, or a method
   *     request that was already sent
   */
  void send(Event event);

  /** Queues a one-way request run on the servant. */
  void send(ServantAction<? super S> action);

  /** Queues a one-way request that runs once {@code guard} holds. */
  void sendWhen(Guard<? super S> guard, ServantAction<? super S> action);

  /** Queues a synchronized request; its result completes the returned future. */
  <R extends @Nullable Object> FutureValue<R> call(ServantFunction<? super S, R> function);

  /** Queues a synchronized request that runs once {@code guard} holds. */
  <R extends @Nullable Object> FutureValue<R> callWhen(
      Guard<? super S> guard, ServantFunction<? super S, R> function);

  /** Queues a synchronized request with no value; the returned future signals its completion. */
  Future signal(ServantAction<? super S> action);

  /** Queues a user-defined synchronized request (paper style); see {@link #send(Event)}. */
  <R extends @Nullable Object> FutureValue<R> call(SynchronizedMethodRequest<? super S, R> request);

  /**
   * Sends a {@link Request}, a data event whose answer, given by the receiving servant's {@link
   * EventProcessor#answer}, completes the returned future. The same call works on an object of this
   * runtime and on one of another runtime reached through a transport (location transparency): the
   * request and its answer then travel as messages, and the answer must be a value the transport's
   * codec allows.
   *
   * @throws IllegalArgumentException the request's destination is not this object
   */
  default <R extends @Nullable Object> FutureValue<R> ask(Request<R> request) {
    return Requests.ask(this, request);
  }

  /**
   * A proxy implementing {@code type} whose calls become requests to this object. {@code type} must
   * be an interface implemented by the servant, and each of its methods must return {@code void} (a
   * one-way request), {@link Future} (a signal) or {@link FutureValue} (a synchronized request).
   * The servant's methods return completed futures ({@link FutureValue#completed}); the proxy's
   * return the futures of the requests. {@code equals}, {@code hashCode} and {@code toString} are
   * answered by the proxy itself.
   *
   * @throws IllegalArgumentException {@code type} is not an interface, is not public (the runtime
   *     calls it from its own package), the servant does not implement it, or a method has another
   *     return type (the message names the method)
   */
  <I> I proxy(Class<I> type);
}

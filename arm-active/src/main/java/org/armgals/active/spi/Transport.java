package org.armgals.active.spi;

import java.util.function.BiConsumer;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.FutureValue;
import org.armgals.active.Request;
import org.armgals.active.TransportStats;
import org.jspecify.annotations.Nullable;

/**
 * Carries events between runtimes. A runtime never uses its transport for its own objects (events
 * between objects of one runtime are handed over in memory, never serialized); it uses it for every
 * event whose destination names another runtime.
 *
 * <p>{@link Transport#inJvm()} links runtimes of one JVM; {@code
 * org.armgals.active.jms.JmsTransport} links runtimes of any JVMs through an Apache ActiveMQ
 * Artemis broker (docs/architecture.md, runtime semantics 5).
 *
 * <p>Threading: {@link #send} is called concurrently by any thread; {@link #attach} and {@link
 * #detach} by the runtime when it starts and stops.
 */
public interface Transport extends AutoCloseable {

  /** Delivers inbound events and requests to one runtime's objects. */
  interface Inbound {
    /**
     * Queues {@code event} to the object at {@code destination}, which names this runtime.
     *
     * @throws org.armgals.active.ObjectStoppedException no such object (stopped or never made)
     */
    void deliver(Address destination, Event event);

    /**
     * Queues {@code request} to the object at {@code destination}, which names this runtime, and
     * returns the future its answer completes.
     *
     * @throws org.armgals.active.ObjectStoppedException no such object (stopped or never made)
     */
    <R extends @Nullable Object> FutureValue<R> ask(Address destination, Request<R> request);

    /**
     * Queues {@code request} to the object at {@code destination}, which names this runtime, and
     * calls {@code answer} once with its outcome, as {@link
     * java.util.concurrent.CompletionStage#whenComplete} would: the value and a null failure, or a
     * null value and the failure (the servant's exception, or an {@link
     * org.armgals.active.ActiveException} if the request never ran). {@code answer} is in place
     * before the request is queued, so it runs on the thread that completes the request, at once:
     * for a transport that sends answers back over the wire, the object's worker sends the answer
     * as soon as the servant returns. It must not block and should not throw.
     *
     * @throws org.armgals.active.ObjectStoppedException no such object (stopped or never made);
     *     {@code answer} is not called then
     */
    <R extends @Nullable Object> void ask(
        Address destination,
        Request<R> request,
        BiConsumer<? super @Nullable R, ? super @Nullable Throwable> answer);

    /**
     * {@code messages} messages of {@code route} to this runtime never arrived (a gap in the
     * route's sequence numbers). The runtime tells its error handler ({@link ErrorHandler#onLost}).
     * Must not throw.
     */
    default void lost(String route, long messages) {}
  }

  /**
   * Makes the runtime named {@code runtime} reachable through this transport.
   *
   * @throws IllegalStateException a runtime of that name is already attached
   */
  void attach(String runtime, Inbound inbound);

  /** Makes {@code runtime} unreachable. Idempotent. */
  void detach(String runtime);

  /**
   * Sends {@code event} to {@code destination} in another runtime.
   *
   * @throws IllegalArgumentException no runtime named {@code destination.runtime()} is reachable
   * @throws org.armgals.active.ActiveException the destination refused the event (stopped object,
   *     full buffer with a rejecting policy)
   */
  void send(Address destination, Event event);

  /**
   * Sends {@code request} to {@code destination} in another runtime; the returned future is
   * completed by the answer (or fails with the answer's failure).
   *
   * @throws UnsupportedOperationException the transport cannot carry requests
   */
  default <R extends @Nullable Object> FutureValue<R> ask(Address destination, Request<R> request) {
    throw new UnsupportedOperationException(
        this + " cannot carry requests; " + request + " was not sent to " + destination);
  }

  /**
   * Whether the runtime should route events between its own objects through this transport too
   * ("JMS everywhere", the paper's own behavior and a benchmark baseline). Default false: local
   * events are handed over in memory.
   */
  default boolean routesLocalEvents() {
    return false;
  }

  /** The transport's figures; default {@link TransportStats#NONE}. */
  default TransportStats stats() {
    return TransportStats.NONE;
  }

  /** Releases what the transport holds. The default does nothing. */
  @Override
  default void close() {}

  /** A transport linking the runtimes of this JVM that share the returned instance. */
  static Transport inJvm() {
    return new InJvmTransport();
  }
}

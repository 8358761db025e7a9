package org.armgals.active.spi;

import org.armgals.active.Address;
import org.armgals.active.Event;

/**
 * Carries events between runtimes. A runtime never uses its transport for its own objects (events
 * between objects of one runtime are handed over in memory, never serialized); it uses it for every
 * event whose destination names another runtime.
 *
 * <p>{@link Transport#inJvm()} links runtimes of one JVM. A transport for runtimes in other JVMs
 * (JMS over Apache ActiveMQ Artemis, DESIGN.md rule 5) is meant to implement this interface.
 *
 * <p>Threading: {@link #send} is called concurrently by any thread; {@link #attach} and {@link
 * #detach} by the runtime when it starts and stops.
 */
public interface Transport extends AutoCloseable {

  /** Delivers inbound events to one runtime's objects. */
  @FunctionalInterface
  interface Inbound {
    /**
     * Queues {@code event} to the object at {@code destination}, which names this runtime.
     *
     * @throws org.armgals.active.ObjectStoppedException no such object (stopped or never made)
     */
    void deliver(Address destination, Event event);
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

  /** Releases what the transport holds. The default does nothing. */
  @Override
  default void close() {}

  /** A transport linking the runtimes of this JVM that share the returned instance. */
  static Transport inJvm() {
    return new InJvmTransport();
  }
}

package org.armgals.active.spi;

import org.armgals.active.Address;
import org.armgals.active.Event;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Where a runtime sends the failures of its objects (an exception while processing an event or a
 * cycle). The failure is also counted, completes the matching future exceptionally and is told to
 * the object's {@link ObjectListener}; the object goes on with its next event.
 *
 * <p>Threading: called on the failing object's thread; must be thread-safe and must not throw.
 */
@FunctionalInterface
public interface ErrorHandler {

  /** {@code object} failed on {@code event} ({@code null} outside an event) with {@code error}. */
  void onError(Address object, @Nullable Event event, Throwable error);

  /**
   * {@code messages} messages of the route {@code route} to this runtime ({@code runtime}) never
   * arrived: the transport found a gap in the route's sequence numbers when a later message came (a
   * broker restart, a send the broker refused). The events themselves are unknown; objects that
   * keep a model of another (the kernel's behavioral metas) resynchronize on their own sequence
   * numbers. Called on the transport's receiving thread; the default logs at WARN.
   */
  default void onLost(String runtime, String route, long messages) {
    LoggerFactory.getLogger("org.armgals.active")
        .warn("runtime {}: {} message(s) of route {} never arrived", runtime, messages, route);
  }

  /** Logs each failure through SLF4J at WARN, with the stack trace. The default. */
  static ErrorHandler logging() {
    Logger log = LoggerFactory.getLogger("org.armgals.active");
    return (object, event, error) ->
        log.warn(
            "active object {} failed on {}", object, event == null ? "its cycle" : event, error);
  }
}

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

  /** Logs each failure through SLF4J at WARN, with the stack trace. The default. */
  static ErrorHandler logging() {
    Logger log = LoggerFactory.getLogger("org.armgals.active");
    return (object, event, error) ->
        log.warn(
            "active object {} failed on {}", object, event == null ? "its cycle" : event, error);
  }
}

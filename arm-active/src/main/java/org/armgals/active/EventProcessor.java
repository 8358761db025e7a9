package org.armgals.active;

/**
 * A servant that takes data events: every queued event that is not a {@link Callable} is handed to
 * {@link #process}, and so is the {@link FutureEvent} of each reply a synchronous object takes. A
 * servant that does not implement this interface only takes method requests; a data event sent to
 * it fails and goes to the error handler.
 *
 * <p>Threading: both methods are called by the owning object only, one call at a time.
 */
public interface EventProcessor {

  /**
   * Whether {@code event} may be processed now, given this servant's state. The default asks the
   * event itself ({@link Event#isProcessable()}).
   */
  default boolean isProcessable(Event event) {
    return event.isProcessable();
  }

  /**
   * Processes one data event.
   *
   * @throws Exception any failure; it goes to the runtime's error handler and the object's {@link
   *     org.armgals.active.spi.ObjectListener}, and the object goes on with its next event
   */
  void process(Event event) throws Exception;
}

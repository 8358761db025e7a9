package org.armgals.active;

import org.jspecify.annotations.Nullable;

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

  /**
   * Answers a {@link Request} sent with {@link ActiveRef#ask}; the result completes the sender's
   * future, in this runtime or across a transport. {@link #isProcessable} guards requests too. The
   * default refuses: a servant that takes requests overrides it.
   *
   * @return the answer, of the type the request names
   * @throws Exception any failure; it completes the sender's future exceptionally
   */
  default @Nullable Object answer(Request<?> request) throws Exception {
    throw new UnsupportedOperationException(
        getClass().getName() + " does not answer requests; it was asked " + request);
  }
}

package org.armgals.active;

import java.time.Duration;
import java.util.concurrent.CompletionStage;

/**
 * The return signal of a synchronized request that has no value (paper §4.1, class {@code Future}):
 * {@link #touch()} waits by necessity until the receiver has processed the request.
 *
 * <p>In the asynchronous world (code in an asynchronous active object, or outside any object)
 * {@code touch} parks only the calling thread; inside an active object that thread is a virtual
 * thread, so only that object waits and no platform thread is held. If the wait would close a
 * wait-for cycle between objects it throws {@link WaitCycleException} instead of hanging.
 *
 * <p>Inside a synchronous (reactive) object the future is a {@link SynchronousFuture}, which never
 * waits: see there.
 *
 * <p>Threading: any thread may call any method; completion happens-before the return of {@code
 * touch} and the completion of {@link #toCompletionStage()}.
 */
public interface Future {

  /** Whether the request has been processed (successfully or not). Never waits. */
  boolean isDone();

  /**
   * Waits by necessity until the request has been processed.
   *
   * @throws RequestFailedException the request failed in the receiver (its servant or its guard
   *     threw); the exception is in the cause chain
   * @throws WaitCycleException waiting would deadlock
   * @throws ObjectStoppedException the receiver was stopped before processing the request
   * @throws FutureInterruptedException the waiting thread was interrupted
   */
  void touch();

  /**
   * As {@link #touch()}, giving up after {@code timeout}.
   *
   * @throws FutureTimeoutException no reply within {@code timeout}
   * @throws IllegalArgumentException {@code timeout} is negative
   */
  void touch(Duration timeout);

  /**
   * A stage completed when this future is, for callers outside the runtime. The stage of a {@link
   * FutureValue} carries its value; a failure completes it exceptionally with the servant's
   * exception.
   */
  CompletionStage<?> toCompletionStage();
}

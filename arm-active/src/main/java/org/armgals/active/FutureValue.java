package org.armgals.active;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.concurrent.CompletionStage;
import org.armgals.active.spi.RemoteAnswer;
import org.jspecify.annotations.Nullable;

/**
 * The return value of a synchronized request (paper §4.1, class {@code FutureValue}): {@link
 * #getValue()} waits by necessity, with the same rules as {@link Future#touch()}.
 *
 * @param <T> the value type
 */
public interface FutureValue<T extends @Nullable Object> extends Future {

  /**
   * The value, waiting by necessity until it is there.
   *
   * @throws RequestFailedException the request failed in the receiver (its servant or its guard
   *     threw); the exception is in the cause chain
   * @throws WaitCycleException waiting would deadlock
   * @throws ObjectStoppedException the receiver was stopped before processing the request
   * @throws FutureInterruptedException the waiting thread was interrupted
   * @throws FutureNotAvailableException in a {@link SynchronousFutureValue} whose value has not
   *     arrived yet
   */
  T getValue();

  /**
   * As {@link #getValue()}, giving up after {@code timeout}.
   *
   * @throws FutureTimeoutException no value within {@code timeout}
   * @throws IllegalArgumentException {@code timeout} is negative
   */
  T getValue(Duration timeout);

  @Override
  CompletionStage<T> toCompletionStage();

  /**
   * A future that already has {@code value}: what the servant behind an {@linkplain ActiveRef#proxy
   * interface proxy} returns from a method declared to return a future.
   */
  static <T extends @Nullable Object> FutureValue<T> completed(T value) {
    return ValueFuture.completed(value);
  }

  /**
   * For transports: a future that the transport completes when the answer of a request it sent to
   * another runtime comes back. {@code from} names where the answer comes from, in failures; the
   * waiters' timeouts are read on {@code time}; a waiter receives the answer itself through {@code
   * receiver} when it can (null: whoever completes the future does).
   */
  static <T extends @Nullable Object> RemoteAnswer<T> remote(
      String from, TimeSource time, RemoteAnswer.@Nullable Receiver receiver) {
    return ValueFuture.remote(from, time, receiver);
  }

  /** A future already failed with {@code failure}. */
  static <T extends @Nullable Object> FutureValue<T> failed(Throwable failure) {
    requireNonNull(failure, "failure");
    return ValueFuture.failed(failure);
  }
}

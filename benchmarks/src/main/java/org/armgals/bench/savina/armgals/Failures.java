package org.armgals.bench.savina.armgals;

import java.util.concurrent.CompletableFuture;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.spi.ErrorHandler;
import org.armgals.bench.savina.Check;
import org.jspecify.annotations.Nullable;

/**
 * The suite's error handler: the first failure of any object fails the run that waits, rather than
 * leaving it to hang until {@link Check#STUCK}. Thread-safe.
 */
final class Failures implements ErrorHandler {
  private final CompletableFuture<Void> first = new CompletableFuture<>();

  @Override
  public void onError(Address object, @Nullable Event event, Throwable error) {
    first.completeExceptionally(
        new IllegalStateException(
            "active object " + object + " failed on " + (event == null ? "its cycle" : event),
            error));
  }

  /**
   * The value of {@code done}, waiting as {@link Check#await} does.
   *
   * @throws IllegalStateException an object failed, or {@code done} did not complete in time
   */
  <T> T await(CompletableFuture<T> done, String what) throws InterruptedException {
    Check.await(CompletableFuture.anyOf(done, first), what);
    return done.join();
  }
}

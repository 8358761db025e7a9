package org.armgals.bench.savina;

import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeoutException;

/** The checks that make a wrong or stuck run fail loudly instead of printing a figure. */
public final class Check {
  /** The longest a run may wait for its work to finish before it is declared stuck. */
  public static final Duration STUCK = Duration.ofSeconds(120);

  private Check() {}

  /**
   * Checks a count.
   *
   * @throws IllegalStateException naming {@code what}, the expected and the actual value
   */
  public static void equal(String what, long expected, long actual) {
    if (expected != actual) {
      throw new IllegalStateException(what + ": expected " + expected + ", got " + actual);
    }
  }

  /**
   * Checks a condition.
   *
   * @throws IllegalStateException with {@code what} as its message
   */
  public static void state(boolean condition, String what) {
    if (!condition) {
      throw new IllegalStateException(what);
    }
  }

  /**
   * The value of {@code done}, waiting at most {@link #STUCK}.
   *
   * @throws IllegalStateException {@code done} failed or did not complete in time
   */
  public static <T> T await(CompletableFuture<T> done, String what) throws InterruptedException {
    try {
      return done.get(STUCK.toMillis(), java.util.concurrent.TimeUnit.MILLISECONDS);
    } catch (ExecutionException e) {
      throw new IllegalStateException(what + " failed", e.getCause());
    } catch (TimeoutException e) {
      throw new IllegalStateException(what + " did not finish within " + STUCK, e);
    }
  }
}

package org.armgals.testkit;

import java.util.ArrayList;
import java.util.List;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.spi.ErrorHandler;
import org.jspecify.annotations.Nullable;

/**
 * The failures of a test's objects, as its runtime's error handler: each is logged as {@link
 * ErrorHandler#logging()} does, and kept for the check after the test.
 */
final class ObjectFailures implements ErrorHandler {
  private static final int SHOWN = 5;

  private final ErrorHandler log = ErrorHandler.logging();
  private final List<String> failures = new ArrayList<>();
  private final List<Throwable> errors = new ArrayList<>();

  @Override
  public void onError(Address object, @Nullable Event event, Throwable error) {
    log.onError(object, event, error);
    synchronized (this) {
      failures.add(object + " failed on " + (event == null ? "its cycle" : event) + ": " + error);
      errors.add(error);
    }
  }

  /**
   * The test's failure if an object of runtime {@code runtime} failed: the first few failures
   * named, the errors attached (the first as the cause); empty otherwise.
   */
  synchronized @Nullable AssertionError check(String runtime) {
    if (failures.isEmpty()) {
      return null;
    }
    StringBuilder message =
        new StringBuilder()
            .append(failures.size())
            .append(" object failure(s) in runtime ")
            .append(runtime)
            .append(" (turn failOnObjectFailures off to provoke failures on purpose):");
    failures.stream().limit(SHOWN).forEach(f -> message.append("\n  ").append(f));
    if (failures.size() > SHOWN) {
      message.append("\n  ... and ").append(failures.size() - SHOWN).append(" more");
    }
    AssertionError e = new AssertionError(message.toString(), errors.get(0));
    errors.stream().skip(1).limit(SHOWN - 1).forEach(e::addSuppressed);
    return e;
  }
}

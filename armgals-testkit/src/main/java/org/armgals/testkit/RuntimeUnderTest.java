package org.armgals.testkit;

import java.time.Duration;
import java.util.List;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.RuntimeStats;
import org.armgals.active.ShutdownMode;
import org.jspecify.annotations.Nullable;

/** A runtime a test was given, with its failures, closed by the extension after the test. */
final class RuntimeUnderTest {
  /** How long the shutdown after a test may take. */
  static final Duration SHUTDOWN = Duration.ofSeconds(10);

  final ActiveRuntime runtime;
  final ObjectFailures failures;
  final boolean failOnObjectFailures;

  /**
   * Whether the test fails when the shutdown is not clean. Not on a manual clock: events that wait
   * for an instant the test never stepped are the test's business, and the shutdown discards them.
   */
  final boolean requireCleanShutdown;

  RuntimeUnderTest(
      ActiveRuntime.Builder builder, boolean failOnObjectFailures, boolean requireCleanShutdown) {
    this.failures = new ObjectFailures();
    this.runtime = builder.errorHandler(failures).jmx(false).build();
    this.failOnObjectFailures = failOnObjectFailures;
    this.requireCleanShutdown = requireCleanShutdown;
  }

  /**
   * Shuts the runtime down (draining) and adds to {@code problems} what the test must fail with:
   * its objects' failures, and a shutdown that was not clean.
   */
  void close(List<Throwable> problems) {
    RuntimeStats before = runtime.stats();
    boolean clean = runtime.shutdown(ShutdownMode.DRAIN, SHUTDOWN);
    if (!clean && requireCleanShutdown) {
      problems.add(
          new AssertionError(
              "runtime "
                  + runtime.name()
                  + " did not shut down cleanly within "
                  + SHUTDOWN.toSeconds()
                  + " s after the test (objects still busy, or events whose guard never opened); it"
                  + " had "
                  + before.objects()
                  + " object(s) and "
                  + before.queuedEvents()
                  + " queued event(s)"));
    }
    if (failOnObjectFailures) {
      @Nullable AssertionError failed = failures.check(runtime.name());
      if (failed != null) {
        problems.add(failed);
      }
    }
  }

  /** Throws the first of {@code problems} with the others suppressed, if there is one. */
  static void throwIfAny(List<Throwable> problems) {
    if (problems.isEmpty()) {
      return;
    }
    Throwable first = problems.get(0);
    problems.stream().skip(1).forEach(first::addSuppressed);
    switch (first) {
      case Error e -> throw e;
      case RuntimeException e -> throw e;
      default -> throw new IllegalStateException(first);
    }
  }
}

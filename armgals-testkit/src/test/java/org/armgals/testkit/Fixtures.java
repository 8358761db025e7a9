package org.armgals.testkit;

import static org.junit.platform.engine.discovery.DiscoverySelectors.selectClass;

import java.util.List;
import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.testkit.engine.EngineTestKit;
import org.junit.platform.testkit.engine.Events;

/** Runs a fixture class of JUnit tests on the Jupiter engine, as a user's build would. */
final class Fixtures {
  private Fixtures() {}

  /** The events of {@code fixture}'s tests. */
  static Events run(Class<?> fixture) {
    return EngineTestKit.engine("junit-jupiter")
        .selectors(selectClass(fixture))
        .execute()
        .testEvents();
  }

  /** Why the failed tests of {@code events} failed. */
  static List<Throwable> failures(Events events) {
    return events.failed().stream()
        .map(e -> e.getPayload(TestExecutionResult.class).orElseThrow())
        .map(r -> r.getThrowable().orElseThrow())
        .toList();
  }
}

package org.armgals.testkit;

import java.lang.reflect.AnnotatedElement;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Clock;
import org.armgals.active.ManualClock;
import org.jspecify.annotations.Nullable;
import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.junit.jupiter.api.extension.ParameterContext;
import org.junit.jupiter.api.extension.ParameterResolutionException;
import org.junit.jupiter.api.extension.ParameterResolver;
import org.junit.platform.commons.support.AnnotationSupport;

/**
 * Gives each test an {@link ActiveRuntime} of its own, as a parameter of the test method and of its
 * {@code @BeforeEach} and {@code @AfterEach} methods (one runtime for the three), and shuts it down
 * after the test. Its settings come from {@link ActiveTest} on the method, else on the class, else
 * {@code ActiveTest}'s defaults.
 *
 * <p>The runtime is named after the test, has {@link ActiveTest#workers()} workers, no MBean, and
 * an error handler that logs each failure of its objects and keeps it. After the test (after its
 * {@code @AfterEach} methods), the runtime is shut down ({@link
 * org.armgals.active.ShutdownMode#DRAIN}, 10 s), and the test fails:
 *
 * <ul>
 *   <li>if one of its objects failed, naming the failures, unless {@link
 *       ActiveTest#failOnObjectFailures()} is off;
 *   <li>on the real clock, if the shutdown was not clean (objects still busy after 10 s, or events
 *       whose guard never opened). On a manual clock, events that wait for an instant the test
 *       never stepped are discarded without failing it.
 * </ul>
 *
 * <p>With {@link ActiveTest#manualClock()}, a test may also take the {@link ManualClock} of its
 * synchronous objects and a {@link Stepper} of it. The runtime itself keeps the system's time for
 * its timeouts (a future's {@code getValue(timeout)}, the shutdown), so that a test never hangs on
 * a clock nobody steps.
 *
 * <p>A constructor or a {@code @BeforeAll} method cannot take the runtime: it is the test's.
 */
public final class ActiveRuntimeExtension implements ParameterResolver, AfterEachCallback {
  private static final ExtensionContext.Namespace NAMESPACE =
      ExtensionContext.Namespace.create(ActiveRuntimeExtension.class);
  private static final AtomicLong RUNS = new AtomicLong();

  /** Made by JUnit. */
  public ActiveRuntimeExtension() {}

  /** What one test was given. */
  private record Given(RuntimeUnderTest runtime, @Nullable ManualClock clock) {}

  @Override
  public boolean supportsParameter(ParameterContext parameter, ExtensionContext context) {
    Class<?> type = parameter.getParameter().getType();
    return type == ActiveRuntime.class || type == ManualClock.class || type == Stepper.class;
  }

  @Override
  public Object resolveParameter(ParameterContext parameter, ExtensionContext context) {
    Class<?> type = parameter.getParameter().getType();
    if (context.getTestMethod().isEmpty()) {
      throw new ParameterResolutionException(
          type.getSimpleName()
              + " is given to test methods and their @BeforeEach and @AfterEach methods, not to "
              + parameter.getDeclaringExecutable()
              + ": each test has a runtime of its own");
    }
    Given given =
        context
            .getStore(NAMESPACE)
            .getOrComputeIfAbsent(Given.class, k -> start(context), Given.class);
    if (type == ActiveRuntime.class) {
      return given.runtime().runtime;
    }
    ManualClock clock = given.clock();
    if (clock == null) {
      throw new ParameterResolutionException(
          type.getSimpleName()
              + " is given only on a manual clock, and "
              + context.getDisplayName()
              + " runs on the real clock: annotate it with @ActiveTest(manualClock = true)");
    }
    return type == ManualClock.class ? clock : Stepper.of(clock);
  }

  @Override
  public void afterEach(ExtensionContext context) {
    Given given = context.getStore(NAMESPACE).remove(Given.class, Given.class);
    if (given == null) {
      return;
    }
    List<Throwable> problems = new ArrayList<>();
    given.runtime().close(problems);
    if (given.clock() != null) {
      given.clock().close();
    }
    RuntimeUnderTest.throwIfAny(problems);
  }

  private static Given start(ExtensionContext context) {
    ActiveTest settings = settings(context);
    if (settings.periodMillis() < 1) {
      throw new ParameterResolutionException(
          "@ActiveTest(periodMillis) must be at least 1, was " + settings.periodMillis());
    }
    String name =
        context.getRequiredTestMethod().getName().replaceAll("[^A-Za-z0-9_-]", "_")
            + "-"
            + RUNS.incrementAndGet();
    ActiveRuntime.Builder builder = ActiveRuntime.builder().name(name).workers(settings.workers());
    ManualClock clock =
        settings.manualClock() ? Clock.manual(Duration.ofMillis(settings.periodMillis())) : null;
    RuntimeUnderTest runtime =
        new RuntimeUnderTest(builder, settings.failOnObjectFailures(), clock == null);
    return new Given(runtime, clock);
  }

  /** The settings of the method, else of its class (or an enclosing one), else the defaults. */
  private static ActiveTest settings(ExtensionContext context) {
    Optional<ActiveTest> found = find(context.getTestMethod().orElse(null));
    for (Class<?> c = context.getTestClass().orElse(null);
        found.isEmpty() && c != null;
        c = c.getEnclosingClass()) {
      found = find(c);
    }
    return found.orElse(Defaults.class.getAnnotation(ActiveTest.class));
  }

  private static Optional<ActiveTest> find(@Nullable AnnotatedElement element) {
    return AnnotationSupport.findAnnotation(element, ActiveTest.class);
  }

  /** Holds {@link ActiveTest}'s defaults. */
  @ActiveTest
  private static final class Defaults {}
}

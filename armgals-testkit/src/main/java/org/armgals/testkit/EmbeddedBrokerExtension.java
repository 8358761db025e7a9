package org.armgals.testkit;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;
import org.armgals.active.jms.EmbeddedBroker;
import org.junit.jupiter.api.extension.AfterAllCallback;
import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.junit.jupiter.api.extension.ParameterContext;
import org.junit.jupiter.api.extension.ParameterResolutionException;
import org.junit.jupiter.api.extension.ParameterResolver;
import org.junit.platform.commons.support.AnnotationSupport;

/**
 * Gives tests of several runtimes an embedded Apache ActiveMQ Artemis broker: a {@link TestBroker}
 * parameter of a test method (and of its {@code @BeforeEach} and {@code @AfterEach} methods, the
 * same one). The broker listens on {@code 127.0.0.1} at a free port, closed to clients without the
 * login generated for the run, besides its in-VM acceptor.
 *
 * <p>By default the tests of a class share one broker, started for the first of them and closed
 * after the last ({@link BrokerTest#brokerPerTest()} gives each test its own, closed after it);
 * each test has a topic prefix of its own either way. After each test (after its {@code AfterEach}
 * methods) the runtimes made by {@link TestBroker#runtime} are shut down, then the transports made
 * by {@link TestBroker#transport()} are closed; the test fails if an object of those runtimes
 * failed or one did not shut down cleanly.
 *
 * <p>The broker is the one arm-active's JMS transport uses; the testkit takes Artemis as an
 * optional dependency, which a test of distribution has on its class path already.
 */
public final class EmbeddedBrokerExtension
    implements ParameterResolver, AfterEachCallback, AfterAllCallback {
  private static final ExtensionContext.Namespace NAMESPACE =
      ExtensionContext.Namespace.create(EmbeddedBrokerExtension.class);
  private static final AtomicLong RUNS = new AtomicLong();
  private static final int PORT_TRIES = 3;

  /** Made by JUnit. */
  public EmbeddedBrokerExtension() {}

  /** The broker of a class, under its context's unique id. */
  private record ClassBroker(EmbeddedBroker broker) {}

  @Override
  public boolean supportsParameter(ParameterContext parameter, ExtensionContext context) {
    return parameter.getParameter().getType() == TestBroker.class;
  }

  @Override
  public Object resolveParameter(ParameterContext parameter, ExtensionContext context) {
    if (context.getTestMethod().isEmpty()) {
      throw new ParameterResolutionException(
          "TestBroker is given to test methods and their @BeforeEach and @AfterEach methods, not"
              + " to "
              + parameter.getDeclaringExecutable()
              + ": each test has topics of its own");
    }
    return context
        .getStore(NAMESPACE)
        .getOrComputeIfAbsent(TestBroker.class, k -> start(context), TestBroker.class);
  }

  @Override
  public void afterEach(ExtensionContext context) {
    TestBroker test = context.getStore(NAMESPACE).remove(TestBroker.class, TestBroker.class);
    if (test == null) {
      return;
    }
    List<Throwable> problems = new ArrayList<>();
    test.close(problems);
    if (perTest(context)) {
      test.broker().close();
    }
    RuntimeUnderTest.throwIfAny(problems);
  }

  @Override
  public void afterAll(ExtensionContext context) {
    ClassBroker shared =
        context.getStore(NAMESPACE).remove(context.getUniqueId(), ClassBroker.class);
    if (shared != null) {
      shared.broker().close();
    }
  }

  private static TestBroker start(ExtensionContext context) {
    EmbeddedBroker broker;
    if (perTest(context)) {
      broker = startOnAFreePort();
    } else {
      ExtensionContext owner = classContext(context);
      broker =
          owner
              .getStore(NAMESPACE)
              .getOrComputeIfAbsent(
                  owner.getUniqueId(), k -> new ClassBroker(startOnAFreePort()), ClassBroker.class)
              .broker();
    }
    String prefix =
        "test-"
            + context.getRequiredTestMethod().getName().replaceAll("[^A-Za-z0-9_-]", "_")
            + "-"
            + RUNS.incrementAndGet();
    boolean failOnObjectFailures =
        AnnotationSupport.findAnnotation(context.getRequiredTestMethod(), BrokerTest.class)
            .or(() -> classAnnotation(context))
            .map(BrokerTest::failOnObjectFailures)
            .orElse(true);
    return new TestBroker(broker, prefix, failOnObjectFailures);
  }

  /** The context of the test's class (the innermost, for a nested test). */
  private static ExtensionContext classContext(ExtensionContext context) {
    ExtensionContext c = context;
    while (c.getTestMethod().isPresent() && c.getParent().isPresent()) {
      c = c.getParent().get();
    }
    return c;
  }

  private static boolean perTest(ExtensionContext context) {
    return classAnnotation(context).map(BrokerTest::brokerPerTest).orElse(false);
  }

  /** The annotation of the test's class, or of the nearest enclosing class that has one. */
  private static Optional<BrokerTest> classAnnotation(ExtensionContext context) {
    for (Class<?> c = context.getTestClass().orElse(null); c != null; c = c.getEnclosingClass()) {
      Optional<BrokerTest> found = AnnotationSupport.findAnnotation(c, BrokerTest.class);
      if (found.isPresent()) {
        return found;
      }
    }
    return Optional.empty();
  }

  /**
   * A broker on a port that was free a moment ago; another process may take it in between, so a few
   * ports are tried.
   */
  private static EmbeddedBroker startOnAFreePort() {
    IllegalStateException last = null;
    for (int i = 0; i < PORT_TRIES; i++) {
      try {
        return EmbeddedBroker.start(freePort());
      } catch (IllegalStateException e) {
        last = e;
      }
    }
    throw new IllegalStateException(
        "no embedded broker started on a free port of 127.0.0.1 in " + PORT_TRIES + " tries", last);
  }

  private static int freePort() {
    try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      return s.getLocalPort();
    } catch (IOException e) {
      throw new UncheckedIOException("no free port on the loopback address", e);
    }
  }
}

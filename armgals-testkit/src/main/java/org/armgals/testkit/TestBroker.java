package org.armgals.testkit;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.List;
import java.util.function.UnaryOperator;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.jms.EmbeddedBroker;
import org.armgals.active.jms.JmsTransport;

/**
 * What one test of {@link EmbeddedBrokerExtension} is given: the embedded broker, a topic prefix of
 * its own, and transports and runtimes on them that the extension closes after the test (the
 * runtimes first, then the transports).
 *
 * <p>The broker listens on {@code 127.0.0.1} at a free port with a login generated for the run
 * ({@link EmbeddedBroker#nettyUrl()}, {@link EmbeddedBroker#user()}, {@link
 * EmbeddedBroker#password()}), for runtimes of other JVMs; the runtimes of this JVM use its in-VM
 * acceptor.
 *
 * <p>Threading: the test's thread.
 */
public final class TestBroker {
  private final EmbeddedBroker broker;
  private final String prefix;
  private final boolean failOnObjectFailures;
  private final List<RuntimeUnderTest> runtimes = new ArrayList<>();
  private final List<JmsTransport> transports = new ArrayList<>();

  TestBroker(EmbeddedBroker broker, String prefix, boolean failOnObjectFailures) {
    this.broker = broker;
    this.prefix = prefix;
    this.failOnObjectFailures = failOnObjectFailures;
  }

  /** The broker. */
  public EmbeddedBroker broker() {
    return broker;
  }

  /** The test's topic prefix: no other test's runtimes hear what this test's send. */
  public String prefix() {
    return prefix;
  }

  /**
   * A transport builder on the broker's in-VM acceptor with the test's prefix; what it builds is
   * the caller's to close (see {@link #transport(UnaryOperator)} for one the extension closes).
   */
  public JmsTransport.Builder transportBuilder() {
    return JmsTransport.builder().broker(broker.inVmUrl()).prefix(prefix);
  }

  /** {@link #transportBuilder()}, built; closed after the test. */
  public JmsTransport transport() {
    return transport(b -> b);
  }

  /**
   * A transport built from {@link #transportBuilder()} as {@code settings} refine it (codec
   * allow-lists, guarantees); closed after the test.
   */
  public JmsTransport transport(UnaryOperator<JmsTransport.Builder> settings) {
    requireNonNull(settings, "settings");
    JmsTransport t = settings.apply(transportBuilder()).build();
    transports.add(t);
    return t;
  }

  /**
   * A runtime named {@code name} on {@code transport}, with 2 workers and no MBean, shut down after
   * the test like the runtime of {@link ActiveRuntimeExtension}: the test fails if one of its
   * objects failed (unless {@link BrokerTest#failOnObjectFailures()} is off) or if it did not shut
   * down cleanly.
   */
  public ActiveRuntime runtime(String name, JmsTransport transport) {
    return runtime(name, transport, b -> b);
  }

  /**
   * {@link #runtime(String, JmsTransport)} with the builder refined by {@code settings} (workers, a
   * time source); the error handler and the MBean stay the extension's.
   */
  public ActiveRuntime runtime(
      String name, JmsTransport transport, UnaryOperator<ActiveRuntime.Builder> settings) {
    requireNonNull(name, "name");
    requireNonNull(transport, "transport");
    requireNonNull(settings, "settings");
    RuntimeUnderTest r =
        new RuntimeUnderTest(
            settings.apply(ActiveRuntime.builder().name(name).workers(2).transport(transport)),
            failOnObjectFailures,
            true);
    runtimes.add(r);
    return r.runtime;
  }

  /** Closes the runtimes, then the transports, newest first; adds what the test must fail with. */
  void close(List<Throwable> problems) {
    for (int i = runtimes.size() - 1; i >= 0; i--) {
      runtimes.get(i).close(problems);
    }
    for (int i = transports.size() - 1; i >= 0; i--) {
      try {
        transports.get(i).close();
      } catch (RuntimeException e) {
        problems.add(e);
      }
    }
    runtimes.clear();
    transports.clear();
  }

  @Override
  public String toString() {
    return "TestBroker[" + broker.inVmUrl() + ", prefix " + prefix + "]";
  }
}

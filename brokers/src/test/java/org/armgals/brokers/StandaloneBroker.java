package org.armgals.brokers;

import static java.util.Objects.requireNonNull;

import jakarta.jms.Connection;
import jakarta.jms.JMSException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import org.apache.activemq.artemis.jms.client.ActiveMQConnectionFactory;
import org.armgals.active.TimeSource;
import org.jspecify.annotations.Nullable;

/**
 * One broker instance created from the distribution, run as a process of its own ({@code artemis
 * run}) and bound to 127.0.0.1 with login required. It can be started, stopped, killed and started
 * again on the same port, as the fault tests need.
 *
 * <p>Not thread-safe: one test thread drives it (starting, stopping); clients may use {@link
 * #connectionFactory()} from any thread.
 */
final class StandaloneBroker implements AutoCloseable {
  /** The line Artemis prints once its acceptors are up and it serves clients. */
  static final String ACTIVE = "AMQ221007";

  private static final Duration STOP_GRACE = Duration.ofSeconds(20);

  private final BrokerSpec spec;
  private final Path instance;
  private final ArtemisDistribution distribution;
  private final TimeSource time;
  private @Nullable ChildProcess process;
  private @Nullable Tls tls;
  private int starts;

  StandaloneBroker(
      BrokerSpec spec, Path instance, ArtemisDistribution distribution, TimeSource time) {
    this.spec = requireNonNull(spec, "spec");
    this.instance = requireNonNull(instance, "instance");
    this.distribution = requireNonNull(distribution, "distribution");
    this.time = requireNonNull(time, "time");
  }

  BrokerSpec spec() {
    return spec;
  }

  Path instance() {
    return instance;
  }

  String url() {
    return spec.url();
  }

  /** The TLS material, if the acceptor takes TLS only. */
  Optional<Tls> tls() {
    return Optional.ofNullable(tls);
  }

  /**
   * Makes the broker's one acceptor take TLS only, with {@code tls}'s key store, by rewriting its
   * URL in {@code etc/broker.xml}; clients of {@link #connectionFactory()} then trust its trust
   * store. Only before the broker is started.
   */
  void useTls(Tls tls) throws IOException {
    requireNonNull(tls, "tls");
    if (process != null || this.tls != null) {
      throw new IllegalStateException(
          "TLS is set before the first start, once; broker " + spec.name() + " is " + this);
    }
    Path config = instance.resolve("etc/broker.xml");
    String xml = Files.readString(config);
    String acceptor = ">" + url() + "?";
    int at = xml.indexOf(acceptor);
    if (at < 0 || xml.indexOf(acceptor, at + 1) >= 0) {
      throw new IllegalStateException(
          "expected exactly one acceptor '" + acceptor + "' in " + config);
    }
    Files.writeString(config, xml.replace(acceptor, acceptor + tls.acceptorParameters()));
    this.tls = tls;
  }

  /** The URL with the client's TLS options, if the broker takes TLS. */
  String clientUrl() {
    Tls material = tls;
    return material == null ? url() : url() + "?" + material.clientQuery();
  }

  boolean isRunning() {
    return process != null && process.isAlive();
  }

  /**
   * Starts the broker and returns once it is active and a client with the right credentials has
   * connected; if that does not happen within {@code timeout}, kills it and throws with its last
   * lines of output.
   */
  void start(Duration timeout) throws InterruptedException {
    if (process != null) {
      throw new IllegalStateException("broker " + spec.name() + " is already started: " + process);
    }
    starts++;
    ChildProcess started =
        ChildProcess.start(
            "broker " + spec.name(),
            distribution.command(instance.resolve("bin/artemis"), List.of("run")),
            instance.resolve("log").resolve("run-" + starts + ".out"),
            time);
    try {
      started.awaitLine(
          "'" + ACTIVE + "' (server is now active)", line -> line.contains(ACTIVE), timeout);
      try (Connection connection = connectionFactory().createConnection()) {
        connection.start();
      }
    } catch (JMSException e) {
      started.kill();
      throw new IllegalStateException(
          "broker "
              + spec.name()
              + " is active but refused its own user; its last lines:\n"
              + started.tail(),
          e);
    } catch (InterruptedException | RuntimeException | Error e) {
      started.kill();
      throw e;
    }
    process = started;
  }

  /** Stops the broker gracefully (SIGTERM: Artemis's shutdown hook), killing it if it hangs. */
  void stop() throws InterruptedException {
    ChildProcess running = requireStarted();
    process = null;
    running.stop(STOP_GRACE);
  }

  /** Kills the broker at once (SIGKILL), as a crash or a pulled plug would. */
  void kill() throws InterruptedException {
    ChildProcess running = requireStarted();
    process = null;
    running.kill();
  }

  /** A connection factory for the broker's user; each call a new one. */
  ActiveMQConnectionFactory connectionFactory() {
    return new ActiveMQConnectionFactory(clientUrl(), spec.user().user(), spec.user().password());
  }

  /** The broker's last lines of output, or a note that it is not running. */
  String tail() {
    ChildProcess running = process;
    return running == null ? "(broker " + spec.name() + " is not running)" : running.tail();
  }

  private ChildProcess requireStarted() {
    ChildProcess running = process;
    if (running == null) {
      throw new IllegalStateException("broker " + spec.name() + " is not started");
    }
    return running;
  }

  @Override
  public void close() {
    ChildProcess running = process;
    process = null;
    if (running != null) {
      running.close();
    }
  }

  @Override
  public String toString() {
    return "broker " + spec.name() + " at " + url() + " in " + instance;
  }
}

package org.armgals.brokers;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.armgals.active.TimeSource;
import org.armgals.brokers.BrokerSpec.ClusterSpec;
import org.armgals.brokers.BrokerSpec.Credentials;
import org.junit.jupiter.api.extension.AfterAllCallback;
import org.junit.jupiter.api.extension.BeforeAllCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * Creates and starts standalone brokers before a test class's first test and stops them after its
 * last, failed tests or not; register it as a {@code static} field with {@code @RegisterExtension}.
 * One broker (or cluster) serves the whole class, since a broker takes seconds to start.
 *
 * <p>{@link #standalone} gives one broker; {@link #cluster} gives brokers that form a symmetric
 * cluster over static connectors on 127.0.0.1 with on-demand message load balancing, each knowing
 * every other as a peer.
 */
final class BrokerExtension implements BeforeAllCallback, AfterAllCallback {
  static final Duration START_TIMEOUT = Duration.ofSeconds(60);

  private final String name;
  private final int size;
  private final boolean clustered;
  private final boolean tls;
  private final boolean persistent;
  private final List<StandaloneBroker> brokers = new ArrayList<>();

  private BrokerExtension(
      String name, int size, boolean clustered, boolean tls, boolean persistent) {
    this.name = name;
    this.size = size;
    this.clustered = clustered;
    this.tls = tls;
    this.persistent = persistent;
  }

  /** One standalone broker named {@code name}, persistence off. */
  static BrokerExtension standalone(String name) {
    return new BrokerExtension(name, 1, false, false, false);
  }

  /** One standalone broker named {@code name} with a journal (persistence on). */
  static BrokerExtension standalonePersistent(String name) {
    return new BrokerExtension(name, 1, false, false, true);
  }

  /** One standalone broker whose acceptor takes TLS only, with a key made for the test class. */
  static BrokerExtension standaloneWithTls(String name) {
    return new BrokerExtension(name, 1, false, true, false);
  }

  /** A symmetric cluster of {@code size} brokers named {@code name-1}, {@code name-2}, .... */
  static BrokerExtension cluster(String name, int size) {
    if (size < 2) {
      throw new IllegalArgumentException("a cluster needs at least 2 brokers, was " + size);
    }
    return new BrokerExtension(name, size, true, false, false);
  }

  /** The broker, or the first of the cluster. */
  StandaloneBroker broker() {
    return broker(0);
  }

  /** The {@code index}-th broker, from 0. */
  StandaloneBroker broker(int index) {
    if (brokers.size() != size) {
      throw new IllegalStateException("the brokers of " + name + " are not started");
    }
    return brokers.get(index);
  }

  @Override
  public void beforeAll(ExtensionContext context) throws Exception {
    ArtemisDistribution distribution = ArtemisDistribution.fromSystemProperties();
    List<Integer> ports = FreePorts.take(size);
    Credentials user = Credentials.random("armgals");
    Credentials clusterUser = Credentials.random("armgals-cluster");
    try {
      for (int i = 0; i < size; i++) {
        int port = ports.get(i);
        Optional<ClusterSpec> cluster =
            clustered
                ? Optional.of(
                    new ClusterSpec(clusterUser, ports.stream().filter(p -> p != port).toList()))
                : Optional.empty();
        String brokerName = clustered ? name + "-" + (i + 1) : name;
        StandaloneBroker broker =
            distribution.create(new BrokerSpec(brokerName, port, user, cluster, persistent));
        brokers.add(broker);
        if (tls) {
          broker.useTls(
              Tls.generate(
                  broker.instance().getParent(), distribution.javaHome(), TimeSource.system()));
        }
      }
      for (StandaloneBroker broker : brokers) {
        broker.start(START_TIMEOUT);
      }
    } catch (Exception | Error e) {
      closeAll(e);
      throw e;
    }
  }

  @Override
  public void afterAll(ExtensionContext context) throws Exception {
    Exception failure = new IllegalStateException("stopping the brokers of " + name + " failed");
    closeAll(failure);
    if (failure.getSuppressed().length > 0) {
      throw failure;
    }
  }

  private void closeAll(Throwable failure) {
    for (StandaloneBroker broker : brokers) {
      try {
        broker.close();
      } catch (RuntimeException e) {
        failure.addSuppressed(e);
      }
    }
    brokers.clear();
  }
}

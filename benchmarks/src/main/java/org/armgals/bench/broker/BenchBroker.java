package org.armgals.bench.broker;

import jakarta.jms.ConnectionFactory;
import java.io.IOException;
import org.apache.activemq.artemis.core.config.impl.ConfigurationImpl;
import org.apache.activemq.artemis.core.server.embedded.EmbeddedActiveMQ;
import org.apache.activemq.artemis.jms.client.ActiveMQConnectionFactory;

/**
 * The one broker every implementation of the benchmark runs over: an embedded Artemis with
 * persistence off, an in-VM acceptor and a netty acceptor bound to 127.0.0.1.
 *
 * <p>Security is off: the broker lives as long as the benchmark's JVM and listens on loopback only.
 * A broker reached beyond loopback must require credentials (docs/deployment-cluster.md).
 */
final class BenchBroker implements AutoCloseable {
  private final EmbeddedActiveMQ server;
  private final int nettyPort;

  private BenchBroker(EmbeddedActiveMQ server, int nettyPort) {
    this.server = server;
    this.nettyPort = nettyPort;
  }

  static BenchBroker start(int nettyPort) throws Exception {
    ConfigurationImpl config = new ConfigurationImpl();
    config.setPersistenceEnabled(false);
    config.setSecurityEnabled(false);
    config.setJMXManagementEnabled(false);
    config.addAcceptorConfiguration("invm", "vm://0");
    config.addAcceptorConfiguration("netty", "tcp://127.0.0.1:" + nettyPort);
    EmbeddedActiveMQ server = new EmbeddedActiveMQ();
    server.setConfiguration(config);
    server.start();
    return new BenchBroker(server, nettyPort);
  }

  /** The URL a client of {@code transport} connects to. */
  String url(Transport transport) {
    return switch (transport) {
      case INVM -> "vm://0";
      case NETTY -> "tcp://127.0.0.1:" + nettyPort;
    };
  }

  ConnectionFactory connectionFactory(Transport transport) {
    return new ActiveMQConnectionFactory(url(transport));
  }

  @Override
  public void close() throws IOException {
    try {
      server.stop();
    } catch (IOException | RuntimeException e) {
      throw e;
    } catch (Exception e) {
      throw new IOException("stopping the embedded broker failed", e);
    }
  }
}

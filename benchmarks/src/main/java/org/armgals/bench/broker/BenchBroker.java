package org.armgals.bench.broker;

import jakarta.jms.ConnectionFactory;
import org.apache.activemq.artemis.jms.client.ActiveMQConnectionFactory;
import org.armgals.active.EmbeddedBroker;

/**
 * The one broker every implementation of the benchmark runs over: the runtime's own {@link
 * EmbeddedBroker} (persistence off, security off, an in-VM acceptor) with a netty acceptor bound to
 * 127.0.0.1, so that the raw baseline and armgals meet the very same broker.
 */
final class BenchBroker implements AutoCloseable {
  private final EmbeddedBroker broker;
  private final String nettyUrl;

  private BenchBroker(EmbeddedBroker broker) {
    this.broker = broker;
    this.nettyUrl =
        broker
            .nettyUrl()
            .orElseThrow(() -> new IllegalStateException("the broker has no netty acceptor"));
  }

  static BenchBroker start(int nettyPort) {
    return new BenchBroker(EmbeddedBroker.start(nettyPort));
  }

  /** The URL a client of {@code transport} connects to. */
  String url(Transport transport) {
    return switch (transport) {
      case INVM -> broker.inVmUrl();
      case NETTY -> nettyUrl;
    };
  }

  ConnectionFactory connectionFactory(Transport transport) {
    return new ActiveMQConnectionFactory(url(transport));
  }

  @Override
  public void close() {
    broker.close();
  }
}

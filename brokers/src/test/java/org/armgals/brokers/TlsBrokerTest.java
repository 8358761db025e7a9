package org.armgals.brokers;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import jakarta.jms.JMSException;
import java.time.Duration;
import org.apache.activemq.artemis.jms.client.ActiveMQConnectionFactory;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.jms.JmsTransport;
import org.armgals.brokers.RuntimeNode.Counter;
import org.armgals.brokers.RuntimeNode.Sum;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * A standalone broker whose one acceptor takes TLS only (a self-signed key made for the test
 * class): clients that trust its certificate connect, runtimes talk through it with the transport's
 * TLS options, and plain or untrusting clients are refused.
 */
class TlsBrokerTest {
  private static final Duration WAIT = Duration.ofSeconds(30);

  @RegisterExtension
  static final BrokerExtension BROKERS = BrokerExtension.standaloneWithTls("tls");

  @Test
  void aClientThatTrustsTheBrokersCertificateExchangesMessages() throws Exception {
    assertThat(Topics.exchange(BROKERS.broker().connectionFactory(), "over-tls", 10))
        .isEqualTo(Topics.numbered("m", 10));
  }

  @Test
  void aClientWithoutTlsIsRefused() {
    StandaloneBroker broker = BROKERS.broker();
    // The TLS acceptor never answers a plain handshake: wait 2 s for it, not the default 30 s.
    ActiveMQConnectionFactory plain =
        new ActiveMQConnectionFactory(
            broker.url() + "?callTimeout=2000",
            broker.spec().user().user(),
            broker.spec().user().password());
    assertThatThrownBy(() -> plain.createConnection().close()).isInstanceOf(JMSException.class);
  }

  @Test
  void aClientThatDoesNotTrustTheBrokersCertificateIsRefused() {
    StandaloneBroker broker = BROKERS.broker();
    ActiveMQConnectionFactory untrusting =
        new ActiveMQConnectionFactory(
            broker.url() + "?sslEnabled=true",
            broker.spec().user().user(),
            broker.spec().user().password());
    assertThatThrownBy(() -> untrusting.createConnection().close())
        .isInstanceOf(JMSException.class);
  }

  @Test
  void runtimesTalkThroughTheBrokerWithTheTransportsTlsOptions() {
    StandaloneBroker broker = BROKERS.broker();
    Tls tls = broker.tls().orElseThrow();
    JmsTransport.Builder builder =
        RuntimeNode.transport(
                broker.url(), broker.spec().user().user(), broker.spec().user().password(), "tls")
            .brokerOption("sslEnabled", "true")
            .brokerOption("trustStorePath", tls.trustStore().toString())
            .brokerOption("trustStorePassword", tls.password())
            .brokerOption("trustStoreType", "PKCS12");
    try (JmsTransport ta = builder.build();
        JmsTransport tb = builder.build();
        ActiveRuntime a = RuntimeNode.runtime("a", ta);
        ActiveRuntime b = RuntimeNode.runtime("b", tb)) {
      ActiveObject<Counter> counter = b.spawn(new Counter());

      assertThat(
              a.<Counter>ref(counter.address())
                  .ask(new Sum(null, counter.address(), 40, 2))
                  .getValue(WAIT))
          .isEqualTo(42);
    }
  }
}

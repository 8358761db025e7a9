package org.armgals.brokers;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import jakarta.jms.JMSException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.apache.activemq.artemis.jms.client.ActiveMQConnectionFactory;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.TimeSource;
import org.armgals.active.jms.EmbeddedBroker;
import org.armgals.active.jms.JmsTransport;
import org.armgals.brokers.RuntimeNode.Counter;
import org.armgals.brokers.RuntimeNode.Sum;
import org.junit.jupiter.api.Test;

/**
 * The embedded broker's netty acceptor with TLS on (a key made for the test with the JDK's
 * keytool): runtimes that trust its certificate and give its login talk through it; a plain client
 * is refused.
 */
class EmbeddedBrokerTlsTest {
  private static final Duration WAIT = Duration.ofSeconds(30);

  @Test
  void runtimesWithTheLoginAndTheTrustTalkOverTlsAndAPlainClientIsRefused() throws Exception {
    Path dir =
        Files.createDirectories(
            Path.of(System.getProperty(ArtemisDistribution.BROKERS_DIR, "target")));
    Tls tls =
        Tls.generate(
            Files.createTempDirectory(dir, "embedded-tls-"),
            Path.of(System.getProperty("java.home")),
            TimeSource.system());
    int port = FreePorts.take(1).get(0);
    try (EmbeddedBroker broker =
        EmbeddedBroker.builder().port(port).tls(tls.keyStore(), tls.password()).start()) {
      String url = broker.nettyUrl().orElseThrow();
      assertThat(url).isEqualTo("tcp://127.0.0.1:" + port + "?sslEnabled=true");
      JmsTransport.Builder builder =
          RuntimeNode.transport(url, broker.user(), broker.password(), "embedded-tls")
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
      try (ActiveMQConnectionFactory plain =
          new ActiveMQConnectionFactory(
              "tcp://127.0.0.1:" + port + "?callTimeout=2000", broker.user(), broker.password())) {
        assertThatThrownBy(() -> plain.createConnection().close()).isInstanceOf(JMSException.class);
      }
    }
  }
}

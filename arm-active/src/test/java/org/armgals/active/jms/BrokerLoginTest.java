package org.armgals.active.jms;

import static org.armgals.active.jms.JmsFixture.WAIT;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import jakarta.jms.Connection;
import jakarta.jms.JMSSecurityException;
import org.apache.activemq.artemis.jms.client.ActiveMQConnectionFactory;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.junit.jupiter.api.Test;

/**
 * The embedded broker is closed by default: its network acceptor refuses clients without the login
 * (generated for the run, or configured), so that nobody without it sends, receives or looks a name
 * up; the transport says so clearly. Clients of the in-VM acceptor need no login.
 */
class BrokerLoginTest {

  @Test
  void theNetworkAcceptorRefusesClientsWithoutTheGeneratedLogin() throws Exception {
    try (EmbeddedBroker broker = EmbeddedBroker.start(JmsFixture.freePort())) {
      String url = broker.nettyUrl().orElseThrow();
      assertThat(broker.password()).hasSize(32);
      try (ActiveMQConnectionFactory f = new ActiveMQConnectionFactory(url)) {
        assertThatThrownBy(f::createConnection).isInstanceOf(JMSSecurityException.class);
        assertThatThrownBy(() -> f.createConnection(broker.user(), "not-" + broker.password()))
            .isInstanceOf(JMSSecurityException.class);
        assertThatThrownBy(() -> f.createConnection("guest", broker.password()))
            .isInstanceOf(JMSSecurityException.class);
      }
      assertThatThrownBy(() -> JmsFixture.transport(url).build())
          .isInstanceOf(IllegalStateException.class)
          .hasMessageContaining("refused the login")
          .hasMessageContaining("no user given");
      assertThatThrownBy(
              () -> JmsFixture.transport("vm://0").broker(url, broker.user(), "wrong").build())
          .isInstanceOf(IllegalStateException.class)
          .hasMessageContaining("refused the login")
          .hasMessageContaining("user '" + broker.user() + "'");

      try (JmsTransport owner = JmsFixture.transport(broker.inVmUrl()).prefix("names").build();
          JmsTransport remote =
              JmsFixture.transport("vm://0")
                  .broker(url, broker.user(), broker.password())
                  .prefix("names")
                  .build();
          ActiveRuntime r = JmsFixture.runtime("owner", owner)) {
        Address sink = r.spawn(new JmsFixture.Sink()).address();
        owner.register("sink", sink);
        assertThat(remote.lookup("sink").getValue(WAIT)).isEqualTo(sink);
      }
    }
  }

  @Test
  void aConfiguredLoginIsTheOneRequired() throws Exception {
    try (EmbeddedBroker broker =
        EmbeddedBroker.builder()
            .port(JmsFixture.freePort())
            .login("crew", "a-long-secret")
            .start()) {
      assertThat(broker.user()).isEqualTo("crew");
      String url = broker.nettyUrl().orElseThrow();
      try (ActiveMQConnectionFactory f = new ActiveMQConnectionFactory(url);
          Connection c = f.createConnection("crew", "a-long-secret")) {
        c.start();
        assertThatThrownBy(() -> f.createConnection("armgals", "a-long-secret"))
            .isInstanceOf(JMSSecurityException.class);
      }
    }
    assertThatThrownBy(() -> EmbeddedBroker.builder().port(1).login("crew", "short"))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("at least 8 characters");
    assertThatThrownBy(() -> EmbeddedBroker.builder().login("crew", "a-long-secret").start())
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("port");
  }
}

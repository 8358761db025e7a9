package org.armgals.brokers;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import jakarta.jms.JMSException;
import jakarta.jms.JMSSecurityException;
import java.nio.file.Files;
import java.util.List;
import org.apache.activemq.artemis.jms.client.ActiveMQConnectionFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

class StandaloneBrokerTest {
  @RegisterExtension static final BrokerExtension BROKERS = BrokerExtension.standalone("single");

  @Test
  void aClientWithTheBrokersCredentialsExchangesMessagesOnATopic() throws Exception {
    assertThat(Topics.exchange(BROKERS.broker().connectionFactory(), "t", 20))
        .isEqualTo(Topics.numbered("m", 20));
  }

  @Test
  void aClientWithoutCredentialsIsRefused() {
    ActiveMQConnectionFactory anonymous = new ActiveMQConnectionFactory(BROKERS.broker().url());
    assertThatThrownBy(() -> anonymous.createConnection().close())
        .isInstanceOf(JMSSecurityException.class);
  }

  @Test
  void aClientWithAWrongPasswordIsRefused() {
    ActiveMQConnectionFactory wrong =
        new ActiveMQConnectionFactory(
            BROKERS.broker().url(), BROKERS.broker().spec().user().user(), "not-the-password");
    assertThatThrownBy(() -> wrong.createConnection().close())
        .isInstanceOf(JMSSecurityException.class);
  }

  @Test
  void theBrokerAcceptsOnLoopbackOnlyAndRequiresLogin() throws Exception {
    String config = Files.readString(BROKERS.broker().instance().resolve("etc/broker.xml"));
    List<String> acceptors =
        config.lines().filter(line -> line.contains("<acceptor name=")).toList();

    assertThat(acceptors)
        .singleElement()
        .asString()
        .contains(">tcp://127.0.0.1:" + BROKERS.broker().spec().port() + "?");
    assertThat(config).doesNotContain("0.0.0.0").doesNotContain("<security-enabled>false");
    assertThat(Files.readString(BROKERS.broker().instance().resolve("etc/bootstrap.xml")))
        .doesNotContain("<web ");
  }

  @Test
  void aStoppedBrokerRefusesClientsAndServesThemAgainOnceStarted() throws Exception {
    StandaloneBroker broker = BROKERS.broker();
    broker.stop();
    assertThat(broker.isRunning()).isFalse();
    assertThatThrownBy(() -> broker.connectionFactory().createConnection().close())
        .isInstanceOf(JMSException.class);

    broker.start(BrokerExtension.START_TIMEOUT);

    assertThat(Topics.exchange(broker.connectionFactory(), "after-restart", 5))
        .isEqualTo(Topics.numbered("m", 5));
  }

  @Test
  void aKilledBrokerStartsAgainOnTheSamePort() throws Exception {
    StandaloneBroker broker = BROKERS.broker();
    broker.kill();
    assertThat(broker.isRunning()).isFalse();

    broker.start(BrokerExtension.START_TIMEOUT);

    assertThat(Topics.exchange(broker.connectionFactory(), "after-kill", 5))
        .isEqualTo(Topics.numbered("m", 5));
  }
}

package org.armgals.brokers;

import static org.assertj.core.api.Assertions.assertThat;

import jakarta.jms.Connection;
import jakarta.jms.DeliveryMode;
import jakarta.jms.MessageConsumer;
import jakarta.jms.MessageProducer;
import jakarta.jms.Session;
import java.nio.file.Files;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

class ClusterTest {
  private static final Duration ROUTE = Duration.ofSeconds(30);
  private static final Duration RECEIVE = Duration.ofSeconds(10);
  private static final int COUNT = 200;

  @RegisterExtension static final BrokerExtension CLUSTER = BrokerExtension.cluster("node", 2);

  @Test
  void aMessagePublishedOnOneBrokerReachesASubscriberOnTheOther() throws Exception {
    try (Connection onA = CLUSTER.broker(0).connectionFactory().createConnection();
        Connection onB = CLUSTER.broker(1).connectionFactory().createConnection()) {
      onA.start();
      onB.start();
      Session sessionA = onA.createSession(false, Session.AUTO_ACKNOWLEDGE);
      Session sessionB = onB.createSession(false, Session.AUTO_ACKNOWLEDGE);
      MessageConsumer consumerB = sessionB.createConsumer(sessionB.createTopic("arm/Entity"));
      MessageProducer producerA = sessionA.createProducer(sessionA.createTopic("arm/Entity"));
      producerA.setDeliveryMode(DeliveryMode.NON_PERSISTENT);

      Topics.awaitRoute(sessionA, producerA, consumerB, ROUTE);
      for (String text : Topics.numbered("e", COUNT)) {
        Topics.send(sessionA, producerA, Topics.DATA, text);
      }

      assertThat(Topics.receiveData(consumerB, COUNT, RECEIVE))
          .isEqualTo(Topics.numbered("e", COUNT));
    }
  }

  @Test
  void subscribersOnBothBrokersEachGetEveryMessageOfTheTopic() throws Exception {
    try (Connection onA = CLUSTER.broker(0).connectionFactory().createConnection();
        Connection onB = CLUSTER.broker(1).connectionFactory().createConnection()) {
      onA.start();
      onB.start();
      Session sessionA = onA.createSession(false, Session.AUTO_ACKNOWLEDGE);
      Session sessionB = onB.createSession(false, Session.AUTO_ACKNOWLEDGE);
      MessageConsumer consumerA = sessionA.createConsumer(sessionA.createTopic("arm/BMeta"));
      MessageConsumer consumerB = sessionB.createConsumer(sessionB.createTopic("arm/BMeta"));
      MessageProducer producerB = sessionB.createProducer(sessionB.createTopic("arm/BMeta"));
      producerB.setDeliveryMode(DeliveryMode.NON_PERSISTENT);

      Topics.awaitRoute(sessionB, producerB, consumerA, ROUTE);
      for (String text : Topics.numbered("s", COUNT)) {
        Topics.send(sessionB, producerB, Topics.DATA, text);
      }

      assertThat(Topics.receiveData(consumerA, COUNT, RECEIVE))
          .isEqualTo(Topics.numbered("s", COUNT));
      assertThat(Topics.receiveData(consumerB, COUNT, RECEIVE))
          .isEqualTo(Topics.numbered("s", COUNT));
    }
  }

  @Test
  void eachBrokerIsConfiguredAsAStaticOnDemandClusterMember() throws Exception {
    for (int i = 0; i < 2; i++) {
      String config = Files.readString(CLUSTER.broker(i).instance().resolve("etc/broker.xml"));
      int peer = CLUSTER.broker(1 - i).spec().port();
      assertThat(config)
          .contains("<message-load-balancing>ON_DEMAND</message-load-balancing>")
          .contains("<static-connectors>")
          .contains(">tcp://127.0.0.1:" + peer + "</connector>");
    }
  }
}

package org.armgals.brokers;

import jakarta.jms.Connection;
import jakarta.jms.JMSException;
import jakarta.jms.Message;
import jakarta.jms.MessageConsumer;
import jakarta.jms.MessageProducer;
import jakarta.jms.Session;
import jakarta.jms.TextMessage;
import jakarta.jms.Topic;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.apache.activemq.artemis.jms.client.ActiveMQConnectionFactory;
import org.armgals.active.TimeSource;
import org.jspecify.annotations.Nullable;

/** Plain Jakarta JMS helpers for the broker tests: send and receive numbered text messages. */
final class Topics {
  static final String KIND = "kind";
  static final String PROBE = "probe";
  static final String DATA = "data";

  private Topics() {}

  static void send(Session session, MessageProducer producer, String kind, String text)
      throws JMSException {
    TextMessage message = session.createTextMessage(text);
    message.setStringProperty(KIND, kind);
    producer.send(message);
  }

  /**
   * Sends probes through {@code producer} until {@code consumer} receives one, or throws at the
   * deadline. A subscription on one cluster member reaches another member asynchronously; until it
   * has, that member drops what is published there (nobody subscribes), so the first message to
   * arrive says the route is up.
   */
  static void awaitRoute(
      Session session, MessageProducer producer, MessageConsumer consumer, Duration timeout)
      throws JMSException {
    TimeSource time = TimeSource.system();
    long deadline = time.nanoTime() + timeout.toNanos();
    for (int i = 0; time.nanoTime() - deadline < 0; i++) {
      send(session, producer, PROBE, "probe " + i);
      Message received = consumer.receive(200);
      if (received != null) {
        return;
      }
    }
    throw new IllegalStateException("no probe went through within " + timeout);
  }

  /**
   * Receives the texts of the next {@code count} data messages (probes skipped), waiting at most
   * {@code timeout} for each.
   */
  static List<String> receiveData(MessageConsumer consumer, int count, Duration timeout)
      throws JMSException {
    List<String> texts = new ArrayList<>();
    while (texts.size() < count) {
      @Nullable Message message = consumer.receive(timeout.toMillis());
      if (message == null) {
        return texts;
      }
      if (DATA.equals(message.getStringProperty(KIND))) {
        texts.add(((TextMessage) message).getText());
      }
    }
    return texts;
  }

  static List<String> numbered(String prefix, int count) {
    List<String> texts = new ArrayList<>();
    for (int i = 0; i < count; i++) {
      texts.add(prefix + i);
    }
    return texts;
  }

  /** Publishes {@code count} messages on a topic and returns what a subscriber received. */
  static List<String> exchange(ActiveMQConnectionFactory factory, String topic, int count)
      throws JMSException {
    try (Connection connection = factory.createConnection()) {
      connection.start();
      Session session = connection.createSession(false, Session.AUTO_ACKNOWLEDGE);
      Topic destination = session.createTopic(topic);
      MessageConsumer consumer = session.createConsumer(destination);
      MessageProducer producer = session.createProducer(destination);
      for (String text : Topics.numbered("m", count)) {
        Topics.send(session, producer, Topics.DATA, text);
      }
      return Topics.receiveData(consumer, count, Duration.ofSeconds(10));
    }
  }
}

package org.armgals.bench.broker;

import jakarta.jms.BytesMessage;
import jakarta.jms.Connection;
import jakarta.jms.DeliveryMode;
import jakarta.jms.Message;
import jakarta.jms.MessageConsumer;
import jakarta.jms.MessageProducer;
import jakarta.jms.Session;
import jakarta.jms.Topic;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import org.armgals.active.TimeSource;
import org.jspecify.annotations.Nullable;

/**
 * The baseline: what a developer writes with the Jakarta JMS API alone. A producer and a consumer
 * on a topic, each on its own connection (as two runtimes would be), non-persistent 64-byte bytes
 * messages; a request/reply is a request on one topic and a reply on another, correlated by id.
 */
final class RawJms implements BrokerImpl {
  private static final long TIMEOUT_SECONDS = 60;

  private final TimeSource time;

  RawJms(TimeSource time) {
    this.time = time;
  }

  @Override
  public String name() {
    return "raw";
  }

  @Override
  public double events(BenchBroker broker, Transport transport, int messages) throws Exception {
    try (Connection receiving = broker.connectionFactory(transport).createConnection();
        Connection sending = broker.connectionFactory(transport).createConnection()) {
      Session in = receiving.createSession(false, Session.AUTO_ACKNOWLEDGE);
      CountDownLatch done = new CountDownLatch(1);
      AtomicInteger received = new AtomicInteger();
      MessageConsumer consumer = in.createConsumer(in.createTopic("bench/events"));
      consumer.setMessageListener(
          message -> {
            if (received.incrementAndGet() == messages) {
              done.countDown();
            }
          });
      receiving.start();

      Session out = sending.createSession(false, Session.AUTO_ACKNOWLEDGE);
      MessageProducer producer = out.createProducer(out.createTopic("bench/events"));
      producer.setDeliveryMode(DeliveryMode.NON_PERSISTENT);
      byte[] payload = new byte[BrokerBench.PAYLOAD_BYTES];
      long start = time.nanoTime();
      for (int i = 0; i < messages; i++) {
        BytesMessage message = out.createBytesMessage();
        message.writeBytes(payload);
        producer.send(message);
      }
      if (!done.await(TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
        throw new IllegalStateException(
            "raw events: "
                + received.get()
                + " of "
                + messages
                + " arrived within "
                + TIMEOUT_SECONDS
                + " s");
      }
      return messages / ((time.nanoTime() - start) / 1e9);
    }
  }

  @Override
  public long[] futureRoundTrips(BenchBroker broker, Transport transport, int requests)
      throws Exception {
    try (Connection serving = broker.connectionFactory(transport).createConnection();
        Connection asking = broker.connectionFactory(transport).createConnection()) {
      Session servant = serving.createSession(false, Session.AUTO_ACKNOWLEDGE);
      Topic replies = servant.createTopic("bench/replies");
      MessageProducer replier = servant.createProducer(replies);
      replier.setDeliveryMode(DeliveryMode.NON_PERSISTENT);
      AtomicReference<@Nullable Exception> failure = new AtomicReference<>();
      byte[] payload = new byte[BrokerBench.PAYLOAD_BYTES];
      servant
          .createConsumer(servant.createTopic("bench/requests"))
          .setMessageListener(
              request -> {
                try {
                  BytesMessage reply = servant.createBytesMessage();
                  reply.writeBytes(payload);
                  reply.setJMSCorrelationID(request.getJMSCorrelationID());
                  replier.send(reply);
                } catch (Exception e) {
                  failure.compareAndSet(null, e);
                }
              });
      serving.start();

      Session caller = asking.createSession(false, Session.AUTO_ACKNOWLEDGE);
      MessageConsumer answers = caller.createConsumer(caller.createTopic("bench/replies"));
      MessageProducer asker = caller.createProducer(caller.createTopic("bench/requests"));
      asker.setDeliveryMode(DeliveryMode.NON_PERSISTENT);
      asking.start();
      long[] nanos = new long[requests];
      for (int i = 0; i < requests; i++) {
        String id = Integer.toString(i);
        BytesMessage request = caller.createBytesMessage();
        request.writeBytes(payload);
        request.setJMSCorrelationID(id);
        long start = time.nanoTime();
        asker.send(request);
        Message reply = answers.receive(TimeUnit.SECONDS.toMillis(TIMEOUT_SECONDS));
        nanos[i] = time.nanoTime() - start;
        if (reply == null || !id.equals(reply.getJMSCorrelationID())) {
          Exception cause = failure.get();
          throw new IllegalStateException(
              "raw futurertt: request "
                  + i
                  + " got "
                  + (reply == null ? "no reply" : "the reply to " + reply.getJMSCorrelationID()),
              cause);
        }
      }
      return nanos;
    }
  }
}

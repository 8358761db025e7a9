package org.armgals.bench.broker;

import jakarta.jms.BytesMessage;
import jakarta.jms.Connection;
import jakarta.jms.DeliveryMode;
import jakarta.jms.JMSException;
import jakarta.jms.Message;
import jakarta.jms.MessageConsumer;
import jakarta.jms.MessageProducer;
import jakarta.jms.Session;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.armgals.active.TimeSource;
import org.jspecify.annotations.Nullable;

/**
 * The baseline: what a developer writes with the Jakarta JMS API alone. A producer and a consumer
 * on a topic, each on its own connection (as two runtimes would be), 64-byte bytes messages; a
 * request/reply is a request on one topic and a reply on another, correlated by id. At most once:
 * non-persistent messages to plain subscriptions. At least once, with Artemis's own means as
 * armgals uses them: persistent messages (each send waits for the broker's confirmation) carrying a
 * duplicate-detection id, to shared durable subscriptions (removed after the run).
 */
final class RawJms implements BrokerImpl {
  private static final long TIMEOUT_SECONDS = 60;

  private static final AtomicInteger RUNS = new AtomicInteger();

  private final TimeSource time;

  RawJms(TimeSource time) {
    this.time = time;
  }

  @Override
  public String name() {
    return "raw";
  }

  @Override
  public double events(BenchBroker broker, Transport transport, Guarantee guarantee, int messages)
      throws Exception {
    boolean alo = guarantee == Guarantee.ALO;
    String run = "raw" + RUNS.incrementAndGet();
    try (Connection receiving = broker.connectionFactory(transport, guarantee).createConnection();
        Connection sending = broker.connectionFactory(transport, guarantee).createConnection()) {
      Session in = receiving.createSession(false, Session.AUTO_ACKNOWLEDGE);
      CountDownLatch done = new CountDownLatch(1);
      AtomicInteger received = new AtomicInteger();
      MessageConsumer consumer = consumer(in, "bench/events", run + "-events", alo);
      consumer.setMessageListener(
          message -> {
            if (received.incrementAndGet() == messages) {
              done.countDown();
            }
          });
      receiving.start();

      Session out = sending.createSession(false, Session.AUTO_ACKNOWLEDGE);
      MessageProducer producer = producer(out, "bench/events", alo);
      byte[] payload = new byte[BrokerBench.PAYLOAD_BYTES];
      long start = time.nanoTime();
      for (int i = 0; i < messages; i++) {
        BytesMessage message = out.createBytesMessage();
        message.writeBytes(payload);
        identify(message, run, i, alo);
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
      double rate = messages / ((time.nanoTime() - start) / 1e9);
      if (alo) {
        consumer.close();
        in.unsubscribe(run + "-events");
      }
      return rate;
    }
  }

  /** A consumer of {@code topic}: durable and shared under {@code name} at least once. */
  private static MessageConsumer consumer(Session s, String topic, String name, boolean alo)
      throws JMSException {
    return alo
        ? s.createSharedDurableConsumer(s.createTopic(topic), name)
        : s.createConsumer(s.createTopic(topic));
  }

  private static MessageProducer producer(Session s, String topic, boolean alo)
      throws JMSException {
    MessageProducer p = s.createProducer(s.createTopic(topic));
    p.setDeliveryMode(alo ? DeliveryMode.PERSISTENT : DeliveryMode.NON_PERSISTENT);
    return p;
  }

  /** At least once, the message's duplicate-detection id. */
  private static void identify(Message m, String run, long n, boolean alo) throws JMSException {
    if (alo) {
      m.setStringProperty(
          org.apache.activemq.artemis.api.core.Message.HDR_DUPLICATE_DETECTION_ID.toString(),
          run + ":" + n);
    }
  }

  @Override
  public long[] futureRoundTrips(
      BenchBroker broker, Transport transport, Guarantee guarantee, int requests) throws Exception {
    boolean alo = guarantee == Guarantee.ALO;
    String run = "raw" + RUNS.incrementAndGet();
    try (Connection serving = broker.connectionFactory(transport, guarantee).createConnection();
        Connection asking = broker.connectionFactory(transport, guarantee).createConnection()) {
      Session servant = serving.createSession(false, Session.AUTO_ACKNOWLEDGE);
      MessageProducer replier = producer(servant, "bench/replies", alo);
      AtomicLong replied = new AtomicLong();
      AtomicReference<@Nullable Exception> failure = new AtomicReference<>();
      byte[] payload = new byte[BrokerBench.PAYLOAD_BYTES];
      MessageConsumer requestsIn = consumer(servant, "bench/requests", run + "-requests", alo);
      requestsIn.setMessageListener(
          request -> {
            try {
              BytesMessage reply = servant.createBytesMessage();
              reply.writeBytes(payload);
              reply.setJMSCorrelationID(request.getJMSCorrelationID());
              identify(reply, run + "-reply", replied.incrementAndGet(), alo);
              replier.send(reply);
            } catch (Exception e) {
              failure.compareAndSet(null, e);
            }
          });
      serving.start();

      Session caller = asking.createSession(false, Session.AUTO_ACKNOWLEDGE);
      MessageConsumer answers = consumer(caller, "bench/replies", run + "-replies", alo);
      MessageProducer asker = producer(caller, "bench/requests", alo);
      asking.start();
      long[] nanos = new long[requests];
      for (int i = 0; i < requests; i++) {
        String id = Integer.toString(i);
        BytesMessage request = caller.createBytesMessage();
        request.writeBytes(payload);
        request.setJMSCorrelationID(id);
        identify(request, run, i, alo);
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
      if (alo) {
        requestsIn.close();
        answers.close();
        servant.unsubscribe(run + "-requests");
        caller.unsubscribe(run + "-replies");
      }
      return nanos;
    }
  }
}

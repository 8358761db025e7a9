package org.armgals.active.jms;

import static org.armgals.active.jms.JmsFixture.WAIT;
import static org.assertj.core.api.Assertions.assertThat;

import jakarta.jms.BytesMessage;
import jakarta.jms.Connection;
import jakarta.jms.DeliveryMode;
import jakarta.jms.JMSException;
import jakarta.jms.MessageProducer;
import jakarta.jms.Session;
import jakarta.jms.Topic;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import org.apache.activemq.artemis.jms.client.ActiveMQConnectionFactory;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.TransportStats;
import org.armgals.active.jms.JmsFixture.Ping;
import org.armgals.active.jms.JmsFixture.Sink;
import org.armgals.active.jms.WireCodecTest.Trap;
import org.junit.jupiter.api.Test;

/**
 * Hostile messages put on the broker by hand, past the transport's own sender: every one is
 * rejected and counted, none builds a type that is not allowed, and the runtime keeps going.
 */
class HostileInputTest {

  static void await(BooleanSupplier condition, Duration timeout) {
    long deadline = System.nanoTime() + timeout.toNanos();
    while (!condition.getAsBoolean()) {
      if (System.nanoTime() - deadline > 0) {
        throw new AssertionError("condition not met within " + timeout);
      }
      LockSupport.parkNanos(1_000_000);
    }
  }

  @Test
  void hostileMessagesAreCountedAsDeadLettersAndTheRuntimeKeepsGoing() throws JMSException {
    try (EmbeddedBroker broker = EmbeddedBroker.start();
        JmsTransport t =
            JmsFixture.transport(broker.inVmUrl()).prefix("hostile").maxMessageBytes(4096).build();
        ActiveRuntime runtime = JmsFixture.runtime("victim", t)) {
      ActiveObject<Sink> sink = runtime.spawn(new Sink());
      Address to = sink.address();
      WireCodec codec = new WireCodec(List.of(JmsFixture.ALLOWED), 1 << 20);
      byte[] valid = WireCodec.body(List.of(codec.encodeValue(new Ping(null, to, 1))));
      ActiveMQConnectionFactory factory = new ActiveMQConnectionFactory(broker.inVmUrl());
      try (Connection c = factory.createConnection()) {
        Session s = c.createSession(false, Session.AUTO_ACKNOWLEDGE);
        Topic entity = s.createTopic(t.topicName(JmsTransport.Topic.ENTITY));
        MessageProducer p = s.createProducer(entity);
        p.setDeliveryMode(DeliveryMode.NON_PERSISTENT);
        Map<String, Object> route = Map.of("arm_msg", "event", "arm_to", "victim");

        // one of each kind of hostile message
        p.send(bytes(s, new byte[] {1, 2, 3}, route)); // garbage
        p.send(bytes(s, valid, Map.of("arm_to", "victim"))); // missing arm_msg
        p.send(bytes(s, valid, Map.of("arm_msg", "nonsense", "arm_to", "victim"))); // unknown kind
        p.send(bytes(s, new byte[8192], route)); // oversized
        p.send(withProps(s.createTextMessage("hello"), route)); // wrong message type
        p.send(
            bytes(
                s,
                WireCodecTest.recordBody(
                    Trap.class.getName(),
                    codec.encodeValue(null),
                    codec.encodeValue(to),
                    codec.encodeValue("x")),
                route)); // unlisted class
        p.send(
            bytes(
                s,
                WireCodecTest.recordBody(
                    Ping.class.getName(),
                    codec.encodeValue(null),
                    codec.encodeValue(to),
                    codec.encodeValue("not a long")),
                route)); // wrong component type
        p.send(
            bytes(s, valid, Map.of("arm_msg", "request", "arm_to", "victim"))); // no node, no corr
        p.send(
            bytes(
                s,
                WireCodec.body(
                    List.of(codec.encodeValue(new Ping(null, new Address("elsewhere", 1), 1)))),
                route)); // addressed to another runtime
        await(() -> t.stats().rejected() == 9, WAIT);

        // then a flood of generated ones, mutations of a valid message and random bytes
        SplittableRandom random = new SplittableRandom(7);
        int n = 100_000;
        for (int i = 0; i < n; i++) {
          p.send(bytes(s, WireCodecTest.generated(random, valid), route));
        }
        await(() -> t.stats().rejected() + t.stats().received() == 9 + n, Duration.ofSeconds(60));
      }
      factory.close();
      TransportStats stats = t.stats();
      assertThat(stats.rejected()).isGreaterThan(50_000);
      assertThat(stats.received()).isGreaterThan(1_000);
      assertThat(stats.lost()).isZero();
      assertThat(stats.duplicates()).isZero();
      assertThat(sink.call(x -> x.count()).getValue(WAIT)).isEqualTo(stats.received());
      assertThat(WireCodecTest.TRAPS_MADE).hasValue(0);

      // and it still works
      long before = sink.call(x -> x.count()).getValue(WAIT);
      JmsTransport other = JmsFixture.transport(broker.inVmUrl()).prefix("hostile").build();
      try (other;
          ActiveRuntime sender = JmsFixture.runtime("sender", other)) {
        sender.ref(to).send(new Ping(null, to, 99));
        sink.callWhen(x -> x.count() > before, x -> true).getValue(WAIT);
      }
      assertThat(runtime.stats().transport().rejected()).isEqualTo(stats.rejected());
    }
  }

  private static BytesMessage bytes(Session s, byte[] body, Map<String, Object> props)
      throws JMSException {
    BytesMessage m = s.createBytesMessage();
    m.writeBytes(body);
    return withProps(m, props);
  }

  /** Each message takes the next place on one route, so that none is counted lost. */
  private static final java.util.concurrent.atomic.AtomicLong PLACE =
      new java.util.concurrent.atomic.AtomicLong();

  private static <M extends jakarta.jms.Message> M withProps(M m, Map<String, Object> props)
      throws JMSException {
    m.setStringProperty("arm_from", "hostile");
    m.setLongProperty("arm_rseq", PLACE.incrementAndGet());
    for (Map.Entry<String, Object> e : props.entrySet()) {
      m.setObjectProperty(e.getKey(), e.getValue());
    }
    return m;
  }
}

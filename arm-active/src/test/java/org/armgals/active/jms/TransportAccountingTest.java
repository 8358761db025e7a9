package org.armgals.active.jms;

import static org.armgals.active.jms.HostileInputTest.await;
import static org.armgals.active.jms.JmsFixture.WAIT;
import static org.assertj.core.api.Assertions.assertThat;

import jakarta.jms.BytesMessage;
import jakarta.jms.Connection;
import jakarta.jms.DeliveryMode;
import jakarta.jms.JMSException;
import jakarta.jms.MessageProducer;
import jakarta.jms.Session;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.apache.activemq.artemis.jms.client.ActiveMQConnectionFactory;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.jms.JmsFixture.Ping;
import org.armgals.active.jms.JmsFixture.Sink;
import org.armgals.active.spi.ErrorHandler;
import org.jspecify.annotations.Nullable;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * What reaches a transport is counted once, in one figure: received, rejected, a duplicate, or an
 * answer nobody waits for; what never reached it is counted lost when the next message of its route
 * arrives, and told to the runtime's error handler. Messages are put on the broker by hand, as a
 * peer transport would send them.
 */
class TransportAccountingTest {
  static EmbeddedBroker broker;
  static ActiveMQConnectionFactory factory;

  @BeforeAll
  static void startBroker() {
    broker = EmbeddedBroker.start();
    factory = new ActiveMQConnectionFactory(broker.inVmUrl());
  }

  @AfterAll
  static void stopBroker() {
    factory.close();
    broker.close();
  }

  /** Records the gaps told to the runtime. */
  static final class Gaps implements ErrorHandler {
    final List<Long> lost = new CopyOnWriteArrayList<>();

    @Override
    public void onError(Address object, @Nullable Event event, Throwable error) {}

    @Override
    public void onLost(String runtime, String route, long messages) {
      lost.add(messages);
    }
  }

  /** A hand-made peer: sends on one topic of the transport's prefix. */
  record Peer(Session session, MessageProducer producer) implements AutoCloseable {
    static Peer on(Connection c, JmsTransport t, JmsTransport.Topic topic) throws JMSException {
      Session s = c.createSession(false, Session.AUTO_ACKNOWLEDGE);
      MessageProducer p = s.createProducer(s.createTopic(t.topicName(topic)));
      p.setDeliveryMode(DeliveryMode.NON_PERSISTENT);
      return new Peer(s, p);
    }

    void send(List<byte[]> values, Map<String, Object> props) throws JMSException {
      BytesMessage m = session.createBytesMessage();
      m.writeBytes(WireCodec.body(values));
      for (Map.Entry<String, Object> e : props.entrySet()) {
        m.setObjectProperty(e.getKey(), e.getValue());
      }
      producer.send(m);
    }

    @Override
    public void close() throws JMSException {
      session.close();
    }
  }

  static final WireCodec CODEC = new WireCodec(List.of(JmsFixture.ALLOWED), 1 << 20);

  static Map<String, Object> event(String to, long rseq, boolean alo) {
    Map<String, Object> props = new java.util.HashMap<>();
    props.put("arm_msg", "event");
    props.put("arm_to", to);
    props.put("arm_from", "peer");
    props.put("arm_rseq", rseq);
    if (alo) {
      props.put("arm_alo", true);
    }
    return props;
  }

  @Test
  void aGapInARouteIsCountedLostAndToldToTheRuntimesErrorHandler() throws Exception {
    Gaps gaps = new Gaps();
    try (JmsTransport t = JmsFixture.transport(broker.inVmUrl()).prefix("gaps").build();
        ActiveRuntime r =
            ActiveRuntime.builder()
                .name("gaps")
                .workers(1)
                .jmx(false)
                .errorHandler(gaps)
                .transport(t)
                .build();
        Connection c = factory.createConnection();
        Peer peer = Peer.on(c, t, JmsTransport.Topic.ENTITY)) {
      ActiveObject<Sink> sink = r.spawn(new Sink());
      Address to = sink.address();
      for (long rseq : new long[] {1, 2, 5, 6, 10}) {
        peer.send(List.of(CODEC.encodeValue(new Ping(null, to, rseq))), event("gaps", rseq, false));
      }
      await(() -> t.stats().received() == 5, WAIT);
      assertThat(t.stats().lost()).isEqualTo(2 + 3);
      assertThat(gaps.lost).containsExactly(2L, 3L);
      assertThat(t.stats().rejected()).isZero();
    }
  }

  @Test
  void anAtLeastOnceMessageThatArrivesAgainIsDeliveredOnceAndCountedDuplicate() throws Exception {
    try (JmsTransport t =
            JmsFixture.transport(broker.inVmUrl())
                .prefix("dups")
                .guarantee(JmsTransport.Guarantee.AT_LEAST_ONCE, Ping.class)
                .build();
        ActiveRuntime r = JmsFixture.runtime("dups", t);
        Connection c = factory.createConnection();
        Peer peer = Peer.on(c, t, JmsTransport.Topic.ENTITY)) {
      ActiveObject<Sink> sink = r.spawn(new Sink());
      Address to = sink.address();
      byte[] one = CODEC.encodeValue(new Ping(null, to, 1));
      byte[] two = CODEC.encodeValue(new Ping(null, to, 2));
      byte[] three = CODEC.encodeValue(new Ping(null, to, 3));
      peer.send(List.of(one), event("dups", 1, true));
      peer.send(List.of(two), event("dups", 2, true));
      peer.send(List.of(two), event("dups", 2, true)); // delivered again
      Map<String, Object> batch = event("dups", 2, true); // 2 again, and 3
      batch.put("arm_msg", "batch");
      batch.put("arm_count", 2);
      peer.send(List.of(two, three), batch);
      await(() -> t.stats().received() + t.stats().duplicates() == 5, WAIT);
      assertThat(t.stats().duplicates()).isEqualTo(2);
      assertThat(t.stats().lost()).isZero();
      List<Long> ns = new ArrayList<>();
      sink.call(s -> s.events).getValue(WAIT).forEach(e -> ns.add(((Ping) e).n()));
      assertThat(ns).containsExactly(1L, 2L, 3L);
    }
  }

  @Test
  void aBatchWithOneBadEventIsRejectedWholeAndCountedOnce() throws Exception {
    try (JmsTransport t = JmsFixture.transport(broker.inVmUrl()).prefix("whole").build();
        ActiveRuntime r = JmsFixture.runtime("whole", t);
        Connection c = factory.createConnection();
        Peer peer = Peer.on(c, t, JmsTransport.Topic.ENTITY)) {
      ActiveObject<Sink> sink = r.spawn(new Sink());
      Address to = sink.address();
      Map<String, Object> batch = event("whole", 1, false);
      batch.put("arm_msg", "batch");
      batch.put("arm_count", 2);
      peer.send(
          List.of(
              CODEC.encodeValue(new Ping(null, to, 1)),
              CODEC.encodeValue(new Ping(null, new Address("elsewhere", 1), 2))),
          batch);
      peer.send(List.of(CODEC.encodeValue(new Ping(null, to, 3))), event("whole", 3, false));
      await(() -> t.stats().received() + t.stats().rejected() >= 2, WAIT);
      assertThat(t.stats().rejected()).isEqualTo(1);
      assertThat(t.stats().received()).isEqualTo(1);
      assertThat(sink.call(s -> s.count()).getValue(WAIT)).isEqualTo(1);
    }
  }

  @Test
  void answersNobodyWaitsForAreReadAndCountedWithoutARequest() throws Exception {
    try (JmsTransport t =
            JmsFixture.transport(broker.inVmUrl())
                .prefix("strays")
                .replyTimeout(java.time.Duration.ofMillis(400))
                .build();
        Connection c = factory.createConnection();
        Peer peer = Peer.on(c, t, JmsTransport.Topic.FUTURE)) {
      String node = ((JmsTransportImpl) t).node();
      for (long i = 1; i <= 1_000; i++) {
        Map<String, Object> props = new java.util.HashMap<>();
        props.put("arm_msg", "answer");
        props.put("arm_node", node);
        props.put("arm_corr", 1_000_000 + i);
        props.put("arm_from", "peer");
        props.put("arm_rseq", i);
        peer.send(List.of(CODEC.encodeValue(null)), props);
      }
      peer.send(List.of(new byte[] {9, 9}), Map.of("arm_node", node)); // garbage
      await(() -> t.stats().unmatched() == 1_000 && t.stats().rejected() == 1, WAIT);
      assertThat(t.stats().received()).isZero();
    }
  }

  @Test
  void aRepeatedLogLineIsLetThroughTwentyTimesThenOnceInAThousand() {
    LogLimiter limiter = new LogLimiter();
    List<Long> logged = new ArrayList<>();
    for (int i = 0; i < 3_000; i++) {
      long n = limiter.tick();
      if (n > 0) {
        logged.add(n);
      }
    }
    assertThat(logged).hasSize(23).startsWith(1L, 2L, 3L).endsWith(20L, 1_000L, 2_000L, 3_000L);
  }
}

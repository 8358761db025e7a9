package org.armgals.active.jms;

import static org.armgals.active.jms.JmsFixture.WAIT;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import jakarta.jms.Connection;
import jakarta.jms.MessageConsumer;
import jakarta.jms.Session;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.LongAdder;
import org.apache.activemq.artemis.api.core.Interceptor;
import org.apache.activemq.artemis.core.protocol.core.impl.PacketImpl;
import org.apache.activemq.artemis.core.remoting.server.RemotingService;
import org.apache.activemq.artemis.jms.client.ActiveMQConnectionFactory;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.FutureTimeoutException;
import org.armgals.active.FutureValue;
import org.armgals.active.Request;
import org.armgals.active.RequestFailedException;
import org.armgals.active.TransportStats;
import org.armgals.active.jms.JmsFixture.Echo;
import org.armgals.active.jms.JmsFixture.Explode;
import org.armgals.active.jms.JmsFixture.Level;
import org.armgals.active.jms.JmsFixture.Measure;
import org.armgals.active.jms.JmsFixture.Ping;
import org.armgals.active.jms.JmsFixture.Reading;
import org.armgals.active.jms.JmsFixture.Secret;
import org.armgals.active.jms.JmsFixture.Sink;
import org.armgals.active.jms.JmsFixture.Sum;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/** Two runtimes on one embedded broker (docs/architecture.md, runtime semantics 5 and 7). */
class JmsTransportTest {
  static EmbeddedBroker broker;

  @BeforeAll
  static void startBroker() {
    broker = EmbeddedBroker.start();
  }

  @AfterAll
  static void stopBroker() {
    broker.close();
  }

  /** Two runtimes, each with its own transport on the shared broker. */
  static final class Pair implements AutoCloseable {
    final JmsTransport ta;
    final JmsTransport tb;
    final ActiveRuntime a;
    final ActiveRuntime b;

    Pair(String prefix) {
      this(JmsFixture.transport(broker.inVmUrl()).prefix(prefix));
    }

    Pair(JmsTransport.Builder builder) {
      ta = builder.build();
      tb = builder.build();
      a = JmsFixture.runtime("a", ta);
      b = JmsFixture.runtime("b", tb);
    }

    @Override
    public void close() {
      a.close();
      b.close();
      ta.close();
      tb.close();
    }
  }

  static void awaitCount(ActiveRef<Sink> sink, long n) {
    sink.callWhen(s -> s.count() >= n, s -> true).getValue(WAIT);
  }

  @Test
  void eventsToAnotherRuntimeArriveInSendOrder() {
    try (Pair p = new Pair("order")) {
      ActiveObject<Sink> sink = p.b.spawn(new Sink());
      ActiveRef<Sink> remote = p.a.ref(sink.address());
      for (int i = 0; i < 2_000; i++) {
        remote.send(new Ping(null, sink.address(), i));
      }
      awaitCount(sink, 2_000);
      List<Long> ns = new ArrayList<>();
      sink.call(s -> s.events).getValue(WAIT).forEach(e -> ns.add(((Ping) e).n()));
      assertThat(ns).hasSize(2_000).isSorted();
      assertThat(p.a.stats().transport().sent()).isEqualTo(2_000);
      assertThat(p.b.stats().transport().received()).isEqualTo(2_000);
    }
  }

  /** Records pings and sums in the order it takes them. */
  static final class Orderly implements EventProcessor {
    final List<Long> seen = new java.util.concurrent.CopyOnWriteArrayList<>();

    @Override
    public void process(Event event) {
      seen.add(((Ping) event).n());
    }

    @Override
    public Object answer(Request<?> request) {
      Sum s = (Sum) request;
      seen.add((long) s.a());
      return s.a();
    }
  }

  @Test
  void eventsAndRequestsFromOneSenderKeepTheirOrderAcrossBatches() {
    try (Pair p = new Pair("mixed")) {
      Orderly servant = new Orderly();
      ActiveObject<Orderly> o = p.b.spawn(servant);
      ActiveRef<Orderly> remote = p.a.ref(o.address());
      List<FutureValue<Integer>> answers = new ArrayList<>();
      List<Long> expected = new ArrayList<>();
      for (int i = 0; i < 3_000; i++) {
        if (i % 10 == 0) {
          answers.add(remote.ask(new Sum(null, o.address(), i, 0)));
        } else {
          remote.send(new Ping(null, o.address(), i));
        }
        expected.add((long) i);
      }
      for (FutureValue<Integer> f : answers) {
        f.getValue(WAIT);
      }
      o.callWhen(s -> s.seen.size() == 3_000, s -> true).getValue(WAIT);
      assertThat(servant.seen).isEqualTo(expected);
      assertThat(p.ta.stats().batches()).isPositive();
    }
  }

  @Test
  void nestedRecordsListsMapsEnumsAndBytesCrossIntact() {
    try (Pair p = new Pair("values")) {
      ActiveObject<Sink> sink = p.b.spawn(new Sink());
      Measure m =
          new Measure(
              null,
              sink.address(),
              new Reading("lidar", 2.5, Level.HIGH, List.of(1, 2, 3)),
              Map.of("x", 1L, "y", -2L),
              new byte[] {1, 2, 3});
      p.a.ref(sink.address()).send(m);
      awaitCount(sink, 1);
      Measure got = (Measure) sink.call(s -> s.events.get(0)).getValue(WAIT);
      assertThat(got.reading()).isEqualTo(m.reading());
      assertThat(got.counts()).isEqualTo(m.counts());
      assertThat(got.raw()).containsExactly(1, 2, 3);
      assertThat(got).isNotSameAs(m);
    }
  }

  @Test
  void theSameAskWorksLocallyAndAcrossRuntimes() {
    try (Pair p = new Pair("ask")) {
      ActiveObject<Sink> sink = p.b.spawn(new Sink());
      FutureValue<Integer> local =
          p.b.<Sink>ref(sink.address()).ask(new Sum(null, sink.address(), 2, 3));
      FutureValue<Integer> remote =
          p.a.<Sink>ref(sink.address()).ask(new Sum(null, sink.address(), 2, 3));
      assertThat(local.getValue(WAIT)).isEqualTo(5);
      assertThat(remote.getValue(WAIT)).isEqualTo(5);
      Reading r = new Reading("sonar", 0.25, Level.LOW, List.of());
      assertThat(
              p.a.<Sink>ref(sink.address()).ask(new Echo(null, sink.address(), r)).getValue(WAIT))
          .isEqualTo(r);
      // two requests out, two answers back; the local ask used no message
      assertThat(p.a.stats().transport().sent()).isEqualTo(2);
      assertThat(p.b.stats().transport().sent()).isEqualTo(2);
    }
  }

  @Test
  void aFailureInTheRemoteServantFailsTheFutureWithItsCause() {
    try (Pair p = new Pair("fail")) {
      ActiveObject<Sink> sink = p.b.spawn(new Sink());
      FutureValue<String> f =
          p.a.<Sink>ref(sink.address()).ask(new Explode(null, sink.address(), "boom"));
      assertThatThrownBy(() -> f.getValue(WAIT))
          .isInstanceOf(RequestFailedException.class)
          .hasRootCauseMessage("failed remotely: java.lang.IllegalStateException: boom");
    }
  }

  @Test
  void eventsInsideOneRuntimeNeverTouchTheBroker() {
    try (Pair p = new Pair("local")) {
      ActiveObject<Sink> sink = p.a.spawn(new Sink());
      ActiveRef<Sink> ref = p.a.ref(sink.address());
      assertThat(ref).isSameAs(sink);
      for (int i = 0; i < 100; i++) {
        ref.send(new Secret(null, sink.address(), "never serialized " + i));
      }
      awaitCount(sink, 100);
      assertThat(p.ta.stats()).isEqualTo(TransportStats.NONE);
    }
  }

  @Test
  void jmsEverywhereRoutesLocalEventsThroughTheBroker() {
    try (Pair p =
        new Pair(JmsFixture.transport(broker.inVmUrl()).prefix("everywhere").jmsEverywhere(true))) {
      ActiveObject<Sink> sink = p.a.spawn(new Sink());
      ActiveRef<Sink> ref = p.a.ref(sink.address());
      for (int i = 0; i < 100; i++) {
        ref.send(new Ping(null, sink.address(), i));
      }
      awaitCount(sink, 100);
      assertThat(ref.ask(new Sum(null, sink.address(), 1, 1)).getValue(WAIT)).isEqualTo(2);
      // 100 events, the request, its answer
      assertThat(p.ta.stats().sent()).isEqualTo(102);
      assertThat(p.ta.stats().received()).isEqualTo(102);
      // code still runs on the local object
      assertThat(ref.call(s -> s.count()).getValue(WAIT)).isEqualTo(100);
    }
  }

  @Test
  void aNameRegisteredInOneRuntimeIsFoundFromAnother() {
    try (Pair p = new Pair("names")) {
      ActiveObject<Sink> sink = p.b.spawn(new Sink());
      p.tb.register("sink", sink.address());
      assertThat(p.tb.lookup("sink").getValue(WAIT)).isEqualTo(sink.address());
      Address found = p.ta.lookup("sink").getValue(WAIT);
      assertThat(found).isEqualTo(sink.address());
      assertThat(p.a.<Sink>ref(found).ask(new Sum(null, found, 20, 22)).getValue(WAIT))
          .isEqualTo(42);
    }
  }

  @Test
  void anUnknownNameFailsAtTheReplyTimeout() {
    try (Pair p =
        new Pair(
            JmsFixture.transport(broker.inVmUrl())
                .prefix("nonames")
                .replyTimeout(Duration.ofMillis(200)))) {
      assertThatThrownBy(() -> p.ta.lookup("nobody").getValue(WAIT))
          .isInstanceOf(FutureTimeoutException.class)
          .hasMessageContaining("nobody");
    }
  }

  @Test
  void eventsThatBackUpTravelSeveralPerMessage() {
    try (Pair p = new Pair("batch")) {
      ActiveObject<Sink> sink = p.b.spawn(new Sink());
      ActiveRef<Sink> remote = p.a.ref(sink.address());
      int n = 20_000;
      for (int i = 0; i < n; i++) {
        remote.send(new Ping(null, sink.address(), i));
      }
      awaitCount(sink, n);
      TransportStats s = p.ta.stats();
      assertThat(s.sent()).isEqualTo(n);
      assertThat(s.batches()).isPositive();
      assertThat(p.tb.stats().received()).isEqualTo(n);
      List<Event> events = sink.call(x -> x.events).getValue(WAIT);
      for (int i = 0; i < n; i++) {
        assertThat(((Ping) events.get(i)).n()).isEqualTo(i);
      }
    }
  }

  @Test
  void transportFiguresAreInTheRuntimesMBean() throws Exception {
    try (JmsTransport ta = JmsFixture.transport(broker.inVmUrl()).prefix("mbean").build();
        JmsTransport tb = JmsFixture.transport(broker.inVmUrl()).prefix("mbean").build();
        ActiveRuntime a = ActiveRuntime.builder().name("mbean-a").transport(ta).build();
        ActiveRuntime b = JmsFixture.runtime("mbean-b", tb)) {
      ActiveObject<Sink> sink = b.spawn(new Sink());
      for (int i = 0; i < 10; i++) {
        a.ref(sink.address()).send(new Ping(null, sink.address(), i));
      }
      awaitCount(sink, 10);
      javax.management.ObjectName name =
          new javax.management.ObjectName(
              "org.armgals:type=ActiveRuntime,name="
                  + javax.management.ObjectName.quote("mbean-a"));
      javax.management.MBeanServer server =
          java.lang.management.ManagementFactory.getPlatformMBeanServer();
      assertThat(server.getAttribute(name, "TransportSent")).isEqualTo(10L);
      assertThat(server.getAttribute(name, "TransportRejected")).isEqualTo(0L);
      assertThat(a.stats().transport()).isEqualTo(ta.stats());
    }
  }

  @Test
  void aTypeNotAllowedIsRefusedAtTheSender() {
    try (Pair p = new Pair("refused")) {
      ActiveObject<Sink> sink = p.b.spawn(new Sink());
      ActiveRef<Sink> remote = p.a.ref(sink.address());
      assertThatThrownBy(() -> remote.send(new Secret(null, sink.address(), "x")))
          .isInstanceOf(IllegalArgumentException.class)
          .hasMessageContaining(Secret.class.getName())
          .hasMessageContaining("allow-list");
    }
  }

  @Test
  void codeCannotCrossButSaysWhatCan() {
    try (Pair p = new Pair("code")) {
      ActiveObject<Sink> sink = p.b.spawn(new Sink());
      ActiveRef<Sink> remote = p.a.ref(sink.address());
      assertThatThrownBy(() -> remote.call(s -> s.count()))
          .isInstanceOf(UnsupportedOperationException.class)
          .hasMessageContaining("ask(Request)");
    }
  }

  /**
   * The transport's own consumers take their messages pre-acknowledged (decision 0034): events,
   * requests and answers between two runtimes send the broker no acknowledgement, which would go
   * ahead of the answer on the connection. A plain consumer acknowledging automatically, on the
   * same broker, is seen to send one.
   */
  @Test
  void roundTripsAndEventsSendTheBrokerNoAcknowledgement() throws Exception {
    LongAdder acks = new LongAdder();
    Interceptor counting =
        (packet, connection) -> {
          if (packet.getType() == PacketImpl.SESS_ACKNOWLEDGE
              || packet.getType() == PacketImpl.SESS_INDIVIDUAL_ACKNOWLEDGE) {
            acks.increment();
          }
          return true;
        };
    RemotingService remoting = ((EmbeddedArtemis) broker).server().getRemotingService();
    remoting.addIncomingInterceptor(counting);
    try {
      try (Pair p = new Pair("noacks")) {
        ActiveObject<Sink> sink = p.b.spawn(new Sink());
        ActiveRef<Sink> remote = p.a.ref(sink.address());
        for (int i = 0; i < 100; i++) {
          remote.send(new Ping(null, sink.address(), i));
          assertThat(remote.ask(new Sum(null, sink.address(), i, 1)).getValue(WAIT))
              .isEqualTo(i + 1);
        }
        awaitCount(sink, 100);
        p.tb.register("noacks-sink", sink.address());
        assertThat(p.ta.lookup("noacks-sink").getValue(WAIT)).isEqualTo(sink.address());
      }
      assertThat(acks.sum()).as("acknowledgements from the transports").isZero();

      ActiveMQConnectionFactory plain = new ActiveMQConnectionFactory(broker.inVmUrl());
      plain.setBlockOnAcknowledge(true); // the acknowledgement is in before receive returns
      try (Connection c = plain.createConnection()) {
        Session s = c.createSession(false, Session.AUTO_ACKNOWLEDGE);
        jakarta.jms.Topic topic = s.createTopic("noacks-control");
        MessageConsumer consumer = s.createConsumer(topic);
        c.start();
        s.createProducer(topic).send(s.createTextMessage("control"));
        assertThat(consumer.receive(WAIT.toMillis())).isNotNull();
      }
      assertThat(acks.sum()).as("acknowledgements from a plain consumer").isPositive();
    } finally {
      remoting.removeIncomingInterceptor(counting);
    }
  }
}

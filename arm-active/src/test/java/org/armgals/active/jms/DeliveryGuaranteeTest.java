package org.armgals.active.jms;

import static org.armgals.active.jms.HostileInputTest.await;
import static org.armgals.active.jms.JmsFixture.WAIT;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.jms.JmsFixture.Ping;
import org.armgals.active.jms.JmsFixture.Sink;
import org.armgals.active.jms.JmsFixture.Sum;
import org.armgals.active.jms.JmsTransport.Guarantee;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The two guarantees on one embedded broker: at-least-once events wait on the broker for a runtime
 * that is away and reach it, in order, when it is back (each received, or refused by a missing
 * object and counted so); at-most-once events sent meanwhile are gone, and counted lost when the
 * next one arrives. (Across a broker restart: the brokers module.)
 */
class DeliveryGuaranteeTest {
  static EmbeddedBroker broker;

  @BeforeAll
  static void startBroker() {
    broker = EmbeddedBroker.start();
  }

  @AfterAll
  static void stopBroker() {
    broker.close();
  }

  /**
   * Spawns a sink in a fresh runtime {@code b} over a fresh transport, and gives it to the test.
   */
  private interface WithSink {
    void run(JmsTransport transport, ActiveObject<Sink> sink) throws Exception;
  }

  private static void inRuntimeB(JmsTransport.Builder builder, WithSink body) throws Exception {
    try (JmsTransport t = builder.build();
        ActiveRuntime b = JmsFixture.runtime("b", t)) {
      body.run(t, b.spawn(new Sink()));
    }
  }

  private static List<Long> ns(ActiveObject<Sink> sink) {
    List<Long> ns = new ArrayList<>();
    sink.call(s -> s.events).getValue(WAIT).forEach(e -> ns.add(((Ping) e).n()));
    return ns;
  }

  @Test
  void atLeastOnceEventsWaitForTheirRuntimeWhileItIsAwayAndArriveInOrder() throws Exception {
    JmsTransport.Builder builder =
        JmsFixture.transport(broker.inVmUrl())
            .prefix("waits")
            .guarantee(Guarantee.AT_LEAST_ONCE, Ping.class);
    Address[] at = new Address[1];
    inRuntimeB(builder, (t, sink) -> at[0] = sink.address());
    Address to = at[0];
    try (JmsTransport ta = builder.build()) {
      for (int i = 1; i <= 300; i++) {
        ta.send(to, new Ping(null, to, i));
      }
      inRuntimeB(
          builder,
          (tb, sink) -> {
            assertThat(sink.address()).isEqualTo(to);
            // They come as soon as the runtime is attached, some or all before the sink is
            // spawned: those are refused by the runtime and counted, never lost.
            await(() -> tb.stats().received() + tb.stats().rejected() == 300, WAIT);
            assertThat(ns(sink))
                .hasSize((int) tb.stats().received())
                .isSorted()
                .doesNotHaveDuplicates();
            assertThat(tb.stats().lost()).isZero();
            assertThat(tb.stats().duplicates()).isZero();
          });
      assertThat(ta.stats().sent()).isEqualTo(300);
    }
  }

  @Test
  void atMostOnceEventsSentWhileTheirRuntimeIsAwayAreCountedLost() throws Exception {
    JmsTransport.Builder builder = JmsFixture.transport(broker.inVmUrl()).prefix("gone");
    Address[] at = new Address[1];
    inRuntimeB(builder, (t, sink) -> at[0] = sink.address());
    Address to = at[0];
    try (JmsTransport ta = builder.build()) {
      for (int i = 1; i <= 300; i++) {
        ta.send(to, new Ping(null, to, i));
      }
      await(() -> ta.stats().sent() == 300, WAIT);
      inRuntimeB(
          builder,
          (tb, sink) -> {
            ta.send(to, new Ping(null, to, 301));
            await(() -> tb.stats().received() == 1, WAIT);
            assertThat(ns(sink)).containsExactly(301L);
            assertThat(tb.stats().lost()).isEqualTo(300);
          });
    }
  }

  @Test
  void anAtLeastOnceRequestIsAnsweredAndATypeOffTheAllowListCannotBeGivenAGuarantee()
      throws Exception {
    JmsTransport.Builder builder =
        JmsFixture.transport(broker.inVmUrl())
            .prefix("asks")
            .guarantee(Guarantee.AT_LEAST_ONCE, Sum.class);
    inRuntimeB(
        builder,
        (tb, sink) -> {
          try (JmsTransport ta = builder.build()) {
            Address to = sink.address();
            assertThat(ta.ask(to, new Sum(null, to, 20, 22)).getValue(WAIT)).isEqualTo(42);
          }
        });
    assertThatThrownBy(
            () ->
                JmsTransport.builder()
                    .broker(broker.inVmUrl())
                    .guarantee(Guarantee.AT_LEAST_ONCE, Ping.class)
                    .build())
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining(Ping.class.getName())
        .hasMessageContaining("allow-list");
  }
}

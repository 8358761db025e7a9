package org.armgals.active.jms;

import static org.armgals.active.jms.HostileInputTest.await;
import static org.armgals.active.jms.JmsFixture.WAIT;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.armgals.active.ActiveException;
import org.armgals.active.Address;
import org.armgals.active.BufferFullException;
import org.armgals.active.FutureValue;
import org.armgals.active.OverflowPolicy;
import org.armgals.active.TimeSource;
import org.armgals.active.jms.JmsFixture.Ping;
import org.armgals.active.jms.JmsFixture.Sum;
import org.junit.jupiter.api.Test;

/**
 * No call waits for the broker: while it is down, {@code send}, {@code publish} and {@code ask}
 * return at once, the outbound queue applies its overflow policy and counts what it drops, and a
 * request's reply timeout counts from the call. Requests to a runtime declared lost fail at once.
 */
class TransportOutageTest {
  private static final Duration REPLY_TIMEOUT = Duration.ofSeconds(3);

  /** A time source stepped by hand. */
  static final class SteppedTime implements TimeSource {
    final AtomicLong now = new AtomicLong(1_000_000_000L);

    @Override
    public long nanoTime() {
      return now.get();
    }

    void advance(Duration d) {
      now.addAndGet(d.toNanos());
    }
  }

  @Test
  void noCallWaitsForABrokerThatIsDownAndTimeoutsCountFromTheCall() {
    int port = JmsFixture.freePort();
    EmbeddedBroker broker = EmbeddedBroker.start(port);
    SteppedTime time = new SteppedTime();
    JmsTransport t =
        JmsFixture.transport("vm://0")
            .broker(broker.nettyUrl().orElseThrow(), broker.user(), broker.password())
            .prefix("outage")
            .outboundQueue(16, OverflowPolicy.dropNewest())
            .replyTimeout(REPLY_TIMEOUT)
            .timeSource(time)
            .brokerOption("retryInterval", "100")
            .build();
    try (t) {
      Address far = new Address("far", 1);
      broker.close();
      await(() -> !((JmsTransportImpl) t).connected(), WAIT);

      List<FutureValue<Integer>> asked = new ArrayList<>();
      assertTimeoutPreemptively(
          Duration.ofSeconds(5),
          () -> {
            for (int i = 0; i < 200; i++) {
              asked.add(t.ask(far, new Sum(null, far, i, 1)));
              t.send(far, new Ping(null, far, i));
              t.publish(JmsTransport.Topic.ENTITY, new Ping(null, far, i));
            }
          });
      assertThat(t.stats().unsent()).isGreaterThan(0);
      assertThat(asked)
          .anySatisfy(
              f ->
                  assertThatThrownBy(() -> f.getValue(Duration.ZERO))
                      .isInstanceOf(BufferFullException.class));

      time.advance(REPLY_TIMEOUT);
      for (FutureValue<Integer> f : asked) {
        assertThatThrownBy(() -> f.getValue(WAIT)).isInstanceOf(ActiveException.class);
      }
    }
  }

  @org.junit.jupiter.params.ParameterizedTest
  @org.junit.jupiter.params.provider.ValueSource(strings = {"reject", "block:PT10S"})
  void aFullOutboundQueueRefusesTheCallerAtOnceWhileTheBrokerIsAway(String policy) {
    int port = JmsFixture.freePort();
    EmbeddedBroker broker = EmbeddedBroker.start(port);
    JmsTransport t =
        JmsFixture.transport("vm://0")
            .broker(broker.nettyUrl().orElseThrow(), broker.user(), broker.password())
            .prefix("reject")
            .outboundQueue(16, OverflowPolicy.parse(policy))
            .brokerOption("retryInterval", "100")
            .build();
    try (t) {
      Address far = new Address("far", 1);
      broker.close();
      await(() -> !((JmsTransportImpl) t).connected(), WAIT);
      assertTimeoutPreemptively(
          Duration.ofSeconds(5),
          () ->
              assertThatThrownBy(
                      () -> {
                        for (int i = 0; i < 200; i++) {
                          t.send(far, new Ping(null, far, i));
                        }
                      })
                  .isInstanceOf(BufferFullException.class)
                  .hasMessageContaining("outbound queue")
                  .hasMessageContaining("16 messages"));
      assertThat(t.stats().unsent()).isZero();
    }
  }

  @Test
  void requestsToARuntimeDeclaredLostFailAtOnceAndOthersWait() {
    try (EmbeddedBroker broker = EmbeddedBroker.start();
        JmsTransport t =
            JmsFixture.transport(broker.inVmUrl())
                .prefix("lost")
                .replyTimeout(Duration.ofMinutes(5))
                .build()) {
      Address ghost = new Address("ghost", 1);
      Address alive = new Address("alive", 1);
      FutureValue<Integer> toGhost = t.ask(ghost, new Sum(null, ghost, 1, 2));
      FutureValue<Integer> toAlive = t.ask(alive, new Sum(null, alive, 1, 2));

      assertThat(t.failRequestsTo("ghost", "was declared lost")).isEqualTo(1);

      assertThatThrownBy(() -> toGhost.getValue(WAIT))
          .isInstanceOf(ActiveException.class)
          .hasMessageContaining("runtime 'ghost' was declared lost before answering");
      assertThat(toAlive.isDone()).isFalse();
    }
  }
}

package org.armgals.brokers;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.FutureTimeoutException;
import org.armgals.active.FutureValue;
import org.armgals.active.jms.JmsTransport;
import org.armgals.brokers.RuntimeNode.Count;
import org.armgals.brokers.RuntimeNode.Counter;
import org.armgals.brokers.RuntimeNode.Ping;
import org.armgals.brokers.RuntimeNode.Sum;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The standalone broker stopped and started again under two runtimes: the runtimes reconnect and
 * their subscriptions come back, and a request whose answer was lost fails at its reply timeout.
 */
class BrokerRestartTest {
  private static final Duration REPLY_TIMEOUT = Duration.ofSeconds(2);
  private static final Duration RECOVERY = Duration.ofSeconds(60);
  private static final Duration WAIT = Duration.ofSeconds(30);

  @RegisterExtension static final BrokerExtension BROKERS = BrokerExtension.standalone("restart");

  private static JmsTransport transport() {
    StandaloneBroker broker = BROKERS.broker();
    return RuntimeNode.transport(
            broker.url(), broker.spec().user().user(), broker.spec().user().password(), "restart")
        .brokerOption("retryInterval", "200")
        .replyTimeout(REPLY_TIMEOUT)
        .build();
  }

  @Test
  void runtimesReconnectAfterABrokerRestartAndALostReplyFailsAtItsTimeout() throws Exception {
    try (JmsTransport ta = transport();
        JmsTransport tb = transport();
        ActiveRuntime a = RuntimeNode.runtime("a", ta);
        ActiveRuntime b = RuntimeNode.runtime("b", tb)) {
      ActiveObject<Counter> counter = b.spawn(new Counter());
      ActiveRef<Counter> remote = a.ref(counter.address());
      for (int i = 0; i < 100; i++) {
        remote.send(new Ping(null, counter.address(), i));
      }
      assertThat(remote.ask(new Count(null, counter.address())).getValue(WAIT)).isEqualTo(100L);

      BROKERS.broker().stop();
      FutureValue<Integer> lost = remote.ask(new Sum(null, counter.address(), 1, 2));
      assertThatThrownBy(() -> lost.getValue(WAIT))
          .isInstanceOf(FutureTimeoutException.class)
          .hasMessageContaining("within " + REPLY_TIMEOUT);

      BROKERS.broker().start(BrokerExtension.START_TIMEOUT);
      RuntimeNode.awaitAnswer(remote, counter.address(), RECOVERY);
      long before = counter.ask(new Count(null, counter.address())).getValue(WAIT);
      for (int i = 0; i < 100; i++) {
        remote.send(new Ping(null, counter.address(), i));
      }
      assertThat(remote.ask(new Count(null, counter.address())).getValue(WAIT))
          .isEqualTo(before + 100);
    }
  }
}

package org.armgals.brokers;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.FutureTimeoutException;
import org.armgals.active.TimeSource;
import org.armgals.active.jms.JmsTransport;
import org.armgals.brokers.RuntimeNode.Count;
import org.armgals.brokers.RuntimeNode.Counter;
import org.armgals.brokers.RuntimeNode.Ping;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * One application over the two-broker cluster: each runtime connects to its own broker, and names,
 * events and futures cross from one broker to the other.
 */
class ClusterApplicationTest {
  private static final Duration ROUTE = Duration.ofSeconds(60);
  private static final Duration WAIT = Duration.ofSeconds(30);

  @RegisterExtension static final BrokerExtension CLUSTER = BrokerExtension.cluster("app", 2);

  private static JmsTransport transport(StandaloneBroker broker) {
    return RuntimeNode.transport(
            broker.url(), broker.spec().user().user(), broker.spec().user().password(), "app")
        .replyTimeout(Duration.ofSeconds(1))
        .build();
  }

  @Test
  void runtimesOnDifferentBrokersOfTheClusterFindEachOtherAndExchangeEventsAndFutures() {
    try (JmsTransport ta = transport(CLUSTER.broker(0));
        JmsTransport tb = transport(CLUSTER.broker(1));
        ActiveRuntime a = RuntimeNode.runtime("a", ta);
        ActiveRuntime b = RuntimeNode.runtime("b", tb)) {
      ActiveObject<Counter> counter = b.spawn(new Counter());
      tb.register("counter", counter.address());

      Address found = lookUpOnceRouted(ta, ROUTE);
      assertThat(found).isEqualTo(counter.address());
      ActiveRef<Counter> remote = a.ref(found);
      RuntimeNode.awaitAnswer(remote, found, ROUTE);
      for (int i = 0; i < 500; i++) {
        remote.send(new Ping(null, found, i));
      }

      assertThat(remote.ask(new Count(null, found)).getValue(WAIT)).isEqualTo(500L);
      assertThat(ta.stats().sent()).isGreaterThanOrEqualTo(500);
      assertThat(tb.stats().received()).isGreaterThanOrEqualTo(500);
    }
  }

  /**
   * Looks the counter up until an answer comes: a subscription made on one broker reaches the other
   * asynchronously, and until it has, a look-up published there finds nobody.
   */
  private static Address lookUpOnceRouted(JmsTransport transport, Duration timeout) {
    TimeSource time = TimeSource.system();
    long deadline = time.nanoTime() + timeout.toNanos();
    FutureTimeoutException last = null;
    while (time.nanoTime() - deadline < 0) {
      try {
        return transport.lookup("counter").getValue(WAIT);
      } catch (FutureTimeoutException e) {
        last = e;
      }
    }
    throw new IllegalStateException("the name did not cross the cluster within " + timeout, last);
  }
}

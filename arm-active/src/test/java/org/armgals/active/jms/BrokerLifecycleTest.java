package org.armgals.active.jms;

import static org.armgals.active.jms.JmsFixture.WAIT;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.netty.util.concurrent.GlobalEventExecutor;
import java.time.Duration;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.stream.Collectors;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Event;
import org.armgals.active.FutureTimeoutException;
import org.armgals.active.FutureValue;
import org.armgals.active.jms.JmsFixture.Ping;
import org.armgals.active.jms.JmsFixture.Sink;
import org.armgals.active.jms.JmsFixture.Sum;
import org.junit.jupiter.api.Test;

/**
 * Embedded brokers start, serve other JVMs' URLs, stop cleanly and come back (docs/architecture.md,
 * runtime semantics 5).
 */
class BrokerLifecycleTest {

  private static Set<Thread> nonDaemonThreads() {
    return Thread.getAllStackTraces().keySet().stream()
        .filter(t -> t.isAlive() && !t.isDaemon())
        .collect(Collectors.toSet());
  }

  @Test
  void closingTheTransportAndItsBrokerLeavesNoNonDaemonThread() throws InterruptedException {
    Set<Thread> before = nonDaemonThreads();
    int port = JmsFixture.freePort();
    try (JmsTransport owner =
            JmsFixture.transport("vm://0").embeddedBroker(port).prefix("threads").build();
        JmsTransport client =
            JmsFixture.transport("vm://0")
                .broker(
                    "tcp://127.0.0.1:" + port,
                    owner.embeddedBroker().orElseThrow().user(),
                    owner.embeddedBroker().orElseThrow().password())
                .prefix("threads")
                .build();
        ActiveRuntime a = JmsFixture.runtime("a", owner);
        ActiveRuntime b = JmsFixture.runtime("b", client)) {
      ActiveObject<Sink> sink = b.spawn(new Sink());
      a.ref(sink.address()).send(new Ping(null, sink.address(), 1));
      sink.callWhen(s -> s.count() == 1, s -> true).getValue(WAIT);
      assertThat(
              a.<Sink>ref(sink.address()).ask(new Sum(null, sink.address(), 1, 2)).getValue(WAIT))
          .isEqualTo(3);
    }
    // Netty's global executor thread ends by itself after a second without tasks.
    assertThat(GlobalEventExecutor.INSTANCE.awaitInactivity(WAIT.toSeconds(), TimeUnit.SECONDS))
        .isTrue();
    long deadline = System.nanoTime() + WAIT.toNanos();
    Set<Thread> left = nonDaemonThreads();
    left.removeAll(before);
    while (!left.isEmpty() && System.nanoTime() - deadline < 0) {
      LockSupport.parkNanos(10_000_000);
      left = nonDaemonThreads();
      left.removeAll(before);
    }
    assertThat(left).as("non-daemon threads left after close").isEmpty();
  }

  @Test
  void aStartedBrokerNamesItsUrlsAndRefusesABadPort() {
    try (EmbeddedBroker b = EmbeddedBroker.start()) {
      assertThat(b.inVmUrl()).startsWith("vm://");
      assertThat(b.nettyUrl()).isEmpty();
    }
    assertThatThrownBy(() -> EmbeddedBroker.start(70_000))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("70000");
  }

  @Test
  void afterABrokerRestartSubscriptionsComeBackAndALostAnswerFailsAtItsTimeout() {
    int port = JmsFixture.freePort();
    String url = "tcp://127.0.0.1:" + port;
    EmbeddedBroker.Builder broker =
        EmbeddedBroker.builder().port(port).login("crew", "a-long-secret");
    EmbeddedBroker first = broker.start();
    EmbeddedBroker second = null;
    JmsTransport.Builder builder =
        JmsFixture.transport("vm://0")
            .broker(url, "crew", "a-long-secret")
            .prefix("restart")
            .brokerOption("retryInterval", "50")
            .replyTimeout(Duration.ofSeconds(2));
    try (JmsTransport ta = builder.build();
        JmsTransport tb = builder.build();
        ActiveRuntime a = JmsFixture.runtime("a", ta);
        ActiveRuntime b = JmsFixture.runtime("b", tb)) {
      Sink servant = new Sink();
      ActiveObject<Sink> sink = b.spawn(servant);
      ActiveRef<Sink> remote = a.ref(sink.address());
      remote.send(new Ping(null, sink.address(), 0));
      sink.callWhen(s -> s.count() == 1, s -> true).getValue(WAIT);

      // a request whose answer does not come before the restart: its object takes nothing
      RemoteContractTest.Gate closed = new RemoteContractTest.Gate();
      closed.open = false;
      ActiveObject<RemoteContractTest.Gate> gate = b.spawn(closed);
      FutureValue<Integer> lost =
          a.<RemoteContractTest.Gate>ref(gate.address()).ask(new Sum(null, gate.address(), 1, 1));
      first.close();
      second = broker.start();

      // events flow again once both transports have reconnected
      long deadline = System.nanoTime() + Duration.ofSeconds(20).toNanos();
      long n = 1;
      while (servant.count() < 2 && System.nanoTime() - deadline < 0) {
        remote.send(new Ping(null, sink.address(), n++));
        LockSupport.parkNanos(50_000_000);
      }
      assertThat(servant.count()).as("events after the restart").isGreaterThanOrEqualTo(2);
      assertThat(remote.ask(new Sum(null, sink.address(), 2, 2)).getValue(WAIT)).isEqualTo(4);
      assertThatThrownBy(() -> lost.getValue(WAIT))
          .isInstanceOf(FutureTimeoutException.class)
          .hasMessageContaining(gate.address().toString())
          .hasMessageContaining("PT2S");
      List<Event> events = servant.events;
      assertThat(events).first().isEqualTo(new Ping(null, sink.address(), 0));
    } finally {
      first.close();
      if (second != null) {
        second.close();
      }
    }
  }
}

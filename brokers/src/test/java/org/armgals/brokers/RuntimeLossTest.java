package org.armgals.brokers;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.armgals.active.ActiveException;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.FutureTimeoutException;
import org.armgals.active.FutureValue;
import org.armgals.active.jms.JmsTransport;
import org.armgals.active.jms.Presence;
import org.armgals.active.spi.PresenceEvent;
import org.armgals.active.spi.PresenceEvent.Joined;
import org.armgals.active.spi.PresenceEvent.Left;
import org.armgals.active.spi.PresenceEvent.Lost;
import org.armgals.brokers.RuntimeNode.Sum;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * A runtime JVM killed (SIGKILL) or ending normally, seen from another runtime through its presence
 * on the standalone broker: lost after four missed beats, or left when it said so; a request in
 * flight to a killed runtime fails as soon as it is declared lost.
 */
class RuntimeLossTest {
  private static final Duration WAIT = Duration.ofSeconds(60);

  @RegisterExtension static final BrokerExtension BROKERS = BrokerExtension.standalone("loss");

  private final BlockingQueue<PresenceEvent> heard = new LinkedBlockingQueue<>();

  private Presence watcher(String prefix) {
    StandaloneBroker broker = BROKERS.broker();
    return Presence.builder()
        .broker(broker.url(), broker.spec().user().user(), broker.spec().user().password())
        .prefix(prefix)
        .runtime("watcher")
        .period(RuntimeNode.PRESENCE_PERIOD)
        .listener(heard::add)
        .build();
  }

  private PresenceEvent next() throws InterruptedException {
    PresenceEvent event = heard.poll(WAIT.toSeconds(), TimeUnit.SECONDS);
    assertThat(event).as("a presence event within %s", WAIT).isNotNull();
    return event;
  }

  private static String runtimeOf(String ready) {
    return ready.substring("ready runtime=".length(), ready.indexOf(" at="));
  }

  @Test
  void aKilledRuntimeJvmIsLostAfterItsMissedBeats() throws Exception {
    try (Presence watcher = watcher("killed");
        ChildProcess node =
            RuntimeNode.launch(BROKERS.broker(), "killed-node", "killed", List.of("serve"))) {
      String runtime = runtimeOf(node.awaitLine("ready", line -> line.startsWith("ready "), WAIT));
      assertThat(next()).isEqualTo(new Joined(runtime));

      node.kill();

      PresenceEvent lost = next();
      assertThat(lost)
          .isInstanceOf(Lost.class)
          .extracting(PresenceEvent::runtime)
          .isEqualTo(runtime);
      assertThat(((Lost) lost).silence())
          .isGreaterThan(RuntimeNode.PRESENCE_PERIOD.multipliedBy(4));
      assertThat(watcher.peers()).doesNotContain(runtime);
    }
  }

  @Test
  void aRequestInFlightToAKilledRuntimeFailsWhenItIsDeclaredLostNotAtItsTimeout() throws Exception {
    StandaloneBroker broker = BROKERS.broker();
    String user = broker.spec().user().user();
    String password = broker.spec().user().password();
    try (JmsTransport transport =
            RuntimeNode.transport(broker.url(), user, password, "inflight")
                .replyTimeout(Duration.ofMinutes(10))
                .build();
        ActiveRuntime runtime = RuntimeNode.runtime("asker", transport);
        Presence watcher =
            Presence.builder()
                .broker(broker.url(), user, password)
                .prefix("inflight")
                .runtime("asker")
                .period(RuntimeNode.PRESENCE_PERIOD)
                .listener(heard::add)
                .failRequestsOf(transport)
                .build();
        ChildProcess node =
            RuntimeNode.launch(broker, "inflight-node", "inflight", List.of("serve"))) {
      String ready = node.awaitLine("ready", line -> line.startsWith("ready "), WAIT);
      String name = runtimeOf(ready);
      assertThat(next()).isEqualTo(new Joined(name));
      assertThat(watcher.peers()).contains(name);
      Address at = transport.lookup("counter").getValue(WAIT);
      ActiveRef<RuntimeNode.Counter> counter = runtime.ref(at);
      assertThat(counter.ask(new Sum(null, at, 1, 2)).getValue(WAIT)).isEqualTo(3);

      node.kill();
      FutureValue<Integer> inFlight = counter.ask(new Sum(null, at, 2, 2));

      assertThatThrownBy(() -> inFlight.getValue(WAIT))
          .isInstanceOf(ActiveException.class)
          .isNotInstanceOf(FutureTimeoutException.class)
          .hasMessageContaining("runtime '" + name + "' was declared lost");
      assertThat(next()).isInstanceOf(Lost.class);
    }
  }

  @Test
  void aRuntimeJvmThatEndsNormallyIsHeardLeaving() throws Exception {
    try (Presence watcher = watcher("ended");
        ChildProcess node =
            RuntimeNode.launch(BROKERS.broker(), "ended-node", "ended", List.of("serve"))) {
      String runtime = runtimeOf(node.awaitLine("ready", line -> line.startsWith("ready "), WAIT));
      assertThat(next()).isEqualTo(new Joined(runtime));

      node.closeInput();

      assertThat(node.awaitExit(WAIT)).isZero();
      assertThat(next()).isEqualTo(new Left(runtime));
      assertThat(watcher.peers()).isEmpty();
    }
  }
}

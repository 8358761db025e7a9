package org.armgals.active.jms;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import java.util.stream.Stream;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Clock;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.FutureValue;
import org.armgals.active.ManualClock;
import org.armgals.active.Mode;
import org.armgals.active.ObjectConfig;
import org.armgals.active.Request;
import org.armgals.active.RequestFailedException;
import org.armgals.active.ShutdownMode;
import org.armgals.active.jms.JmsFixture.Explode;
import org.armgals.active.jms.JmsFixture.Ping;
import org.armgals.active.jms.JmsFixture.Sum;
import org.armgals.active.spi.Transport;
import org.jspecify.annotations.Nullable;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The rules of the active-object contract that concern events from another runtime, for every
 * transport and both modes of the receiver (docs/architecture.md, runtime semantics 1, 2 and 5).
 */
class RemoteContractTest {
  enum Route {
    IN_JVM,
    JMS
  }

  static final Duration WAIT = Duration.ofSeconds(10);
  static EmbeddedBroker broker;

  @BeforeAll
  static void startBroker() {
    broker = EmbeddedBroker.start();
  }

  @AfterAll
  static void stopBroker() {
    broker.close();
  }

  static Stream<Arguments> routes() {
    List<Arguments> all = new ArrayList<>();
    for (Route r : Route.values()) {
      for (Mode m : Mode.values()) {
        all.add(Arguments.of(r, m));
      }
    }
    return all.stream();
  }

  /** A servant that counts pings in order, answers sums, and takes nothing while closed. */
  static final class Gate implements EventProcessor {
    final List<Long> pings = new java.util.concurrent.CopyOnWriteArrayList<>();
    boolean open = true;

    @Override
    public boolean isProcessable(Event event) {
      return open;
    }

    @Override
    public void process(Event event) {
      pings.add(((Ping) event).n());
    }

    @Override
    public @Nullable Object answer(Request<?> request) {
      return switch (request) {
        case Sum s -> s.a() + s.b();
        case Explode x -> throw new IllegalStateException(x.why());
        default -> throw new IllegalArgumentException("unexpected " + request);
      };
    }
  }

  /** Two runtimes on one transport route; objects live "there", senders are "here". */
  static final class TwoRuntimes implements AutoCloseable {
    final Mode mode;
    final ManualClock clock = Clock.manual(Duration.ofMillis(1));
    final List<Transport> transports = new ArrayList<>();
    final ActiveRuntime here;
    final ActiveRuntime there;

    TwoRuntimes(Route route, Mode mode, String prefix) {
      this.mode = mode;
      if (route == Route.IN_JVM) {
        Transport t = Transport.inJvm();
        transports.add(t);
        here = runtime("here", t);
        there = runtime("there", t);
      } else {
        JmsTransport.Builder b = JmsFixture.transport(broker.inVmUrl()).prefix(prefix);
        JmsTransport a = b.build();
        JmsTransport c = b.build();
        transports.add(a);
        transports.add(c);
        here = runtime("here", a);
        there = runtime("there", c);
      }
    }

    private static ActiveRuntime runtime(String name, Transport t) {
      return ActiveRuntime.builder().name(name).workers(2).jmx(false).transport(t).build();
    }

    <S> ActiveObject<S> spawnThere(S servant) {
      return there.spawn(
          servant,
          mode == Mode.ASYNCHRONOUS
              ? ObjectConfig.asynchronous()
              : ObjectConfig.synchronous(clock));
    }

    /** Waits until {@code condition} holds, stepping the clock in synchronous mode. */
    void await(BooleanSupplier condition) {
      long deadline = System.nanoTime() + WAIT.toNanos();
      while (!condition.getAsBoolean()) {
        if (System.nanoTime() - deadline > 0) {
          throw new AssertionError("condition not met within " + WAIT);
        }
        if (mode == Mode.SYNCHRONOUS) {
          clock.step(1);
        } else {
          LockSupport.parkNanos(200_000);
        }
      }
    }

    <T extends @Nullable Object> T get(FutureValue<T> f) {
      await(f::isDone);
      return f.getValue(WAIT);
    }

    @Override
    public void close() {
      here.shutdown(ShutdownMode.CANCEL, WAIT);
      there.shutdown(ShutdownMode.CANCEL, WAIT);
      transports.forEach(Transport::close);
      clock.close();
    }
  }

  private static String prefix(Route r, Mode m, String test) {
    return "contract-" + test + "-" + r + "-" + m;
  }

  @ParameterizedTest(name = "{0} {1}")
  @MethodSource("routes")
  void eventsFromOneSenderAreProcessedInSendOrder(Route route, Mode mode) {
    try (TwoRuntimes t = new TwoRuntimes(route, mode, prefix(route, mode, "order"))) {
      Gate servant = new Gate();
      ActiveObject<Gate> gate = t.spawnThere(servant);
      ActiveRef<Gate> remote = t.here.ref(gate.address());
      List<Long> expected = new ArrayList<>();
      for (long i = 0; i < 500; i++) {
        remote.send(new Ping(null, gate.address(), i));
        expected.add(i);
      }
      t.await(() -> servant.pings.size() == 500);
      assertThat(servant.pings).isEqualTo(expected);
    }
  }

  @ParameterizedTest(name = "{0} {1}")
  @MethodSource("routes")
  void aRemoteEventWaitsForTheReceiversGuard(Route route, Mode mode) {
    try (TwoRuntimes t = new TwoRuntimes(route, mode, prefix(route, mode, "guard"))) {
      Gate closed = new Gate();
      closed.open = false;
      ActiveObject<Gate> gate = t.spawnThere(closed);
      t.here.ref(gate.address()).send(new Ping(null, gate.address(), 7));
      t.await(() -> gate.queueDepth() == 1);
      int processed = t.get(gate.call(g -> g.pings.size()));
      assertThat(processed).isZero();
      gate.send(g -> g.open = true);
      t.await(() -> closed.pings.size() == 1);
      assertThat(closed.pings).containsExactly(7L);
    }
  }

  @ParameterizedTest(name = "{0} {1}")
  @MethodSource("routes")
  void aRemoteRequestIsAnsweredAndItsFailureComesBackWithTheCause(Route route, Mode mode) {
    try (TwoRuntimes t = new TwoRuntimes(route, mode, prefix(route, mode, "ask"))) {
      ActiveObject<Gate> gate = t.spawnThere(new Gate());
      ActiveRef<Gate> remote = t.here.ref(gate.address());
      int sum = t.get(remote.ask(new Sum(null, gate.address(), 40, 2)));
      assertThat(sum).isEqualTo(42);
      FutureValue<String> failed = remote.ask(new Explode(null, gate.address(), "no fuel"));
      t.await(failed::isDone);
      assertThatThrownBy(() -> failed.getValue(WAIT))
          .isInstanceOf(RequestFailedException.class)
          .rootCause()
          .hasMessageContaining("no fuel");
    }
  }
}

package org.armgals.gals;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Request;
import org.armgals.active.jms.JmsTransport;
import org.armgals.testkit.BrokerTest;
import org.armgals.testkit.TestBroker;
import org.jspecify.annotations.Nullable;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Islands in two runtimes, each with its own JMS transport on one embedded broker (the testkit's),
 * exchanging events with {@link CycleContext#emit(Address, Object)}.
 */
@BrokerTest
class IslandsInTwoRuntimesTest {
  static final Duration WAIT = Duration.ofSeconds(10);
  static final AtomicInteger PREFIXES = new AtomicInteger();

  TestBroker broker;

  /** A payload allowed on the wire. */
  public record Tick(String from, long n) {}

  /** A request allowed on the wire. */
  public record Level(@Nullable Address sender, Address destination, String of)
      implements Request<Integer> {}

  /** A payload nobody allowed. */
  public record Secret(String what) {}

  @BeforeEach
  void broker(TestBroker broker) {
    this.broker = broker;
  }

  /**
   * Two runtimes ("east", "west") on one broker, an island in each, on topics of their own; the
   * testkit shuts the runtimes down and closes the transports after the test.
   */
  static final class TwoSides implements AutoCloseable {
    final JmsTransport eastTransport;
    final JmsTransport westTransport;
    final ActiveRuntime eastRuntime;
    final ActiveRuntime westRuntime;
    final Island east;
    final Island west;

    TwoSides(TestBroker broker, Duration eastPeriod, Duration westPeriod) {
      String prefix = broker.prefix() + "/" + PREFIXES.incrementAndGet();
      eastTransport =
          broker.transport(b -> b.prefix(prefix).allow(Emission.class, Tick.class, Level.class));
      westTransport =
          broker.transport(b -> b.prefix(prefix).allow(Emission.class, Tick.class, Level.class));
      eastRuntime = broker.runtime("east", eastTransport);
      westRuntime = broker.runtime("west", westTransport);
      east = Island.builder("east", eastRuntime).period(eastPeriod).jmx(false).build();
      west = Island.builder("west", westRuntime).period(westPeriod).jmx(false).build();
    }

    @Override
    public void close() {
      east.close();
      west.close();
    }
  }

  /** What an entity took, one line per instant with inputs: {@code instant:inputs}. */
  static final class Log {
    final List<String> taken = new CopyOnWriteArrayList<>();
    final List<Object> received = new CopyOnWriteArrayList<>();
    @Nullable Address peer;
    @Nullable Exception refused;
  }

  static Reaction<Log> recorder(String from, boolean emitEachCycle) {
    return c -> {
      Log log = c.state();
      if (!c.inputs().isEmpty()) {
        log.taken.add(c.instant() + ":" + c.inputs());
        log.received.addAll(c.inputs());
      }
      Address peer = log.peer;
      if (emitEachCycle && peer != null) {
        c.emit(peer, new Tick(from, c.instant()));
      }
    };
  }

  static void await(BooleanSupplier condition) {
    long deadline = System.nanoTime() + WAIT.toNanos();
    while (!condition.getAsBoolean()) {
      if (System.nanoTime() - deadline > 0) {
        throw new AssertionError("condition not met within " + WAIT);
      }
      LockSupport.parkNanos(100_000);
    }
  }

  @Test
  void startedIslandsWithDifferentPeriodsExchangeEventsInSendOrder() throws Exception {
    try (TwoSides s = new TwoSides(broker, Duration.ofMillis(2), Duration.ofMillis(5))) {
      Log eastLog = new Log();
      Log westLog = new Log();
      ReactiveEntity<Log> e = s.east.spawn("e", eastLog, recorder("e", true));
      ReactiveEntity<Log> w = s.west.spawn("w", westLog, recorder("w", true));
      s.westTransport.register("w", w.address());
      s.eastTransport.register("e", e.address());
      Address westAddress = s.eastTransport.lookup("w").getValue(WAIT);
      Address eastAddress = s.westTransport.lookup("e").getValue(WAIT);
      assertThat(westAddress).isEqualTo(w.address());
      w.adapt("peer", l -> l.peer = eastAddress);
      e.adapt("peer", l -> l.peer = westAddress);
      s.east.start();
      s.west.start();

      await(() -> westLog.received.size() >= 50 && eastLog.received.size() >= 20);
      s.east.close();
      s.west.close();

      assertThat(ticks(westLog.received, "e")).isSortedAccordingTo(Long::compare);
      assertThat(ticks(eastLog.received, "w")).isSortedAccordingTo(Long::compare);
      assertThat(ticks(westLog.received, "e")).doesNotHaveDuplicates();
      assertThat(ticks(eastLog.received, "w")).doesNotHaveDuplicates();
    }
  }

  private static List<Long> ticks(List<Object> received, String from) {
    List<Long> out = new ArrayList<>();
    for (Object o : received) {
      Tick t = (Tick) o;
      assertThat(t.from()).isEqualTo(from);
      out.add(t.n());
    }
    return out;
  }

  @Test
  void anEventFromAnotherRuntimeIsTakenAtTheFirstReleaseAfterItArrives() {
    try (TwoSides s = new TwoSides(broker, Duration.ofMillis(2), Duration.ofMillis(3))) {
      Log westLog = new Log();
      ReactiveEntity<Log> w = s.west.spawn("w", westLog, recorder("w", false));
      Log eastLog = new Log();
      eastLog.peer = w.address();
      s.east.spawn("e", eastLog, recorder("e", true));
      s.west.step(); // instant 1: nothing yet

      s.east.step(); // emits Tick(e, 1)
      s.east.step(); // emits Tick(e, 2)
      await(() -> IslandImpl.objectOf(w).queueDepth() == 2);
      s.west.step(); // instant 2 takes both, in send order
      s.east.step(); // emits Tick(e, 3), taken at west's release after it arrived
      await(() -> IslandImpl.objectOf(w).queueDepth() == 1);
      s.west.step(); // instant 3

      assertThat(westLog.taken)
          .containsExactly("2:[Tick[from=e, n=1], Tick[from=e, n=2]]", "3:[Tick[from=e, n=3]]");
    }
  }

  @Test
  void aPayloadNotOnTheAllowListIsRefusedAtTheSender() {
    try (TwoSides s = new TwoSides(broker, Duration.ofMillis(1), Duration.ofMillis(1))) {
      Log westLog = new Log();
      ReactiveEntity<Log> w = s.west.spawn("w", westLog, recorder("w", false));
      Log eastLog = new Log();
      s.east.spawn(
          "e",
          eastLog,
          c -> {
            try {
              c.emit(w.address(), new Secret("plans"));
            } catch (IllegalArgumentException refused) {
              c.state().refused = refused;
            }
          });
      s.east.step();

      assertThat(eastLog.refused)
          .isInstanceOf(IllegalArgumentException.class)
          .hasMessageContaining(Secret.class.getName())
          .hasMessageContaining("allow-list");
      assertThat(s.eastTransport.stats().sent()).isZero();
      assertThat(s.westTransport.stats().rejected()).isZero();
    }
  }

  /** An asker: asks once, at its first cycle, and keeps the awaited value. */
  static final class Asker {
    @Nullable AwaitedValue<Integer> level;
  }

  private static AwaitedValue<Integer> askAcross(TwoSides s, ReactiveEntity<?> target) {
    Asker asker = new Asker();
    s.east.spawn(
        "asker",
        asker,
        c -> {
          if (c.instant() == 1) {
            c.state().level =
                c.ask(
                    target.address(),
                    new Level(null, target.address(), "tank"),
                    Duration.ofSeconds(60));
          }
        });
    s.east.step();
    await(() -> IslandImpl.objectOf(target).queueDepth() == 1);
    s.west.step(); // the target answers as it takes the request
    AwaitedValue<Integer> level = asker.level;
    assertThat(level).isNotNull();
    long deadline = System.nanoTime() + WAIT.toNanos();
    while (level.isPending() && System.nanoTime() - deadline < 0) {
      s.east.step(); // the status changes at the beginning of a cycle of the asker
    }
    return level;
  }

  @Test
  void aRequestToAnEntityOfAnotherRuntimeComesBackAsAnAwaitedValue() {
    try (TwoSides s = new TwoSides(broker, Duration.ofMillis(1), Duration.ofMillis(1))) {
      ReactiveEntity<Log> tank = s.west.spawn("tank", new Log(), recorder("tank", false));
      tank.answerWith((state, request) -> ((Level) request).of().length() * 10);
      s.west.step(); // applies answerWith

      AwaitedValue<Integer> level = askAcross(s, tank);

      assertThat(level.status()).isEqualTo(AwaitedValue.Status.AVAILABLE);
      assertThat(level.value()).isEqualTo(40);
    }
  }

  @Test
  void askByAddressWorksInOneRuntimeToo() {
    try (TwoSides s = new TwoSides(broker, Duration.ofMillis(1), Duration.ofMillis(1))) {
      Island other = Island.builder("other", s.eastRuntime).jmx(false).build();
      try (other) {
        ReactiveEntity<Log> tank = other.spawn("tank", new Log(), recorder("tank", false));
        tank.answerWith((state, request) -> 7);
        other.step();
        Asker asker = new Asker();
        s.east.spawn(
            "asker",
            asker,
            c -> {
              if (c.instant() == 1) {
                c.state().level = c.ask(tank.address(), new Level(null, tank.address(), "x"), WAIT);
              }
            });
        s.east.step(); // asks
        other.step(); // answers
        s.east.step(); // takes the answer
        s.east.step(); // settles it

        assertThat(asker.level).isNotNull();
        assertThat(asker.level.status()).isEqualTo(AwaitedValue.Status.AVAILABLE);
        assertThat(asker.level.value()).isEqualTo(7);
        assertThat(s.eastTransport.stats().sent()).isZero();
      }
    }
  }

  @BrokerTest(failOnObjectFailures = false) // the mute entity fails on the request, on purpose
  @Test
  void aRequestToAnEntityThatAnswersNothingFails() {
    try (TwoSides s = new TwoSides(broker, Duration.ofMillis(1), Duration.ofMillis(1))) {
      ReactiveEntity<Log> mute = s.west.spawn("mute", new Log(), recorder("mute", false));

      AwaitedValue<Integer> level = askAcross(s, mute);

      assertThat(level.status()).isEqualTo(AwaitedValue.Status.FAILED);
      assertThat(level.failure()).get().asString().contains("answers no requests").contains("mute");
    }
  }

  @Test
  void withManualSteppingTheExchangeIsReproducible() {
    List<List<String>> first = pingPong();
    List<List<String>> second = pingPong();
    assertThat(second).isEqualTo(first);
    assertThat(first.get(0)).hasSize(10);
    assertThat(first.get(1)).hasSize(9); // west's last tick arrives after east's last step
  }

  /**
   * East and west stepped in turn (east twice per west step: different periods); after each step
   * the test waits until what was emitted has arrived, so each release takes exactly what was sent
   * before it.
   */
  private List<List<String>> pingPong() {
    try (TwoSides s = new TwoSides(broker, Duration.ofMillis(1), Duration.ofMillis(2))) {
      Log eastLog = new Log();
      Log westLog = new Log();
      ReactiveEntity<Log> e = s.east.spawn("e", eastLog, recorder("e", true));
      ReactiveEntity<Log> w = s.west.spawn("w", westLog, recorder("w", true));
      eastLog.peer = w.address();
      westLog.peer = e.address();
      for (int i = 0; i < 10; i++) {
        int sentByEast = 2;
        s.east.step();
        s.east.step();
        await(() -> IslandImpl.objectOf(w).queueDepth() == sentByEast);
        s.west.step();
        await(() -> IslandImpl.objectOf(e).queueDepth() == 1);
      }
      return List.of(List.copyOf(westLog.taken), List.copyOf(eastLog.taken));
    }
  }
}

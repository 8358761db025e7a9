package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Reactive objects on clocks (docs/architecture.md, runtime semantics 3; paper §5.2-5.3). */
class SynchronousModeTest {

  /** A reactive object that logs, per instant, what it received and sends what it is told to. */
  static final class Node implements ReactiveCycle {
    final String name;
    final List<String> log = new ArrayList<>();
    final List<ActiveRef<Node>> peers = new ArrayList<>();
    final SplittableRandom random;
    int received;

    Node(String name, long seed) {
      this.name = name;
      this.random = new SplittableRandom(seed);
    }

    void receive(String from, long sentAt) {
      received++;
      log.add("got " + from + "@" + sentAt);
    }

    @Override
    public void onCycle(long instant) {
      log.add("cycle " + instant + " received=" + received);
      for (ActiveRef<Node> p : peers) {
        if (random.nextInt(3) == 0) {
          String me = name;
          p.send(n -> n.receive(me, instant));
        }
      }
    }
  }

  @Test
  void whatIsEmittedAtInstantKIsSeenAtKPlusOne() {
    try (ManualClock clock = Clock.manual(Duration.ofMillis(10));
        ActiveRuntime rt = ActiveRuntime.builder().jmx(false).build()) {
      List<String> seen = new ArrayList<>();
      final class Receiver implements ReactiveCycle {
        final List<String> inbox = new ArrayList<>();

        @Override
        public void onCycle(long instant) {
          seen.add(instant + ":" + inbox);
          inbox.clear();
        }
      }
      ActiveObject<Receiver> b = rt.spawn(new Receiver(), ObjectConfig.synchronous(clock));
      final class Emitter implements ReactiveCycle {
        @Override
        public void onCycle(long instant) {
          b.send(r -> r.inbox.add("sent@" + instant));
        }
      }
      rt.spawn(new Emitter(), ObjectConfig.synchronous(clock));
      clock.step(3);
      assertThat(seen).containsExactly("1:[]", "2:[sent@1]", "3:[sent@2]");
      assertThat(clock.nanoTime()).isEqualTo(Duration.ofMillis(30).toNanos());
    }
  }

  @Test
  void aReleaseTakesEveryEventWaitingAtThatInstantAndNothingElse() {
    try (ManualClock clock = Clock.manual(Duration.ofMillis(1));
        ActiveRuntime rt = ActiveRuntime.builder().jmx(false).build()) {
      List<Integer> perInstant = new ArrayList<>();
      final class Counter implements ReactiveCycle {
        int n;

        @Override
        public void onCycle(long instant) {
          perInstant.add(n);
          n = 0;
        }
      }
      ActiveObject<Counter> c = rt.spawn(new Counter(), ObjectConfig.synchronous(clock));
      for (int i = 0; i < 5; i++) {
        c.send(x -> x.n++);
      }
      assertThat(c.queueDepth()).isEqualTo(5);
      clock.step();
      c.send(x -> x.n++);
      clock.step();
      clock.step();
      assertThat(perInstant).containsExactly(5, 1, 0);
    }
  }

  /** A reactive object that asks an asynchronous one and never waits for the answer. */
  static final class Asker implements ReactiveCycle {
    final ActiveRef<Oracle> oracle;
    final List<String> log = new ArrayList<>();
    FutureValue<Integer> pending;

    Asker(ActiveRef<Oracle> oracle) {
      this.oracle = oracle;
    }

    @Override
    public void onCycle(long instant) {
      if (pending == null) {
        pending = oracle.call(o -> o.answer);
        log.add(instant + ": asked, " + pending.getClass().getSimpleName());
        try {
          pending.getValue();
          log.add(instant + ": had it at once?");
        } catch (FutureNotAvailableException e) {
          log.add(instant + ": not yet");
        }
      } else if (pending.isDone()) {
        log.add(instant + ": got " + pending.getValue());
        pending = null;
      }
    }
  }

  static final class Oracle {
    int answer = 42;
  }

  @Test
  void synchronousFutureArrivesAsAnEventAndNeverBlocksTheCycle() {
    try (ManualClock clock = Clock.manual(Duration.ofMillis(1));
        ActiveRuntime rt = ActiveRuntime.builder().jmx(false).build()) {
      ActiveObject<Oracle> oracle = rt.spawn(new Oracle());
      Asker asker = new Asker(oracle);
      ActiveObject<Asker> a = rt.spawn(asker, ObjectConfig.synchronous(clock));
      clock.step();
      // The oracle answers asynchronously; the answer is an event taken at a later release.
      oracle.call(o -> o.answer).getValue(Duration.ofSeconds(10));
      clock.stepUntil(() -> a.call(x -> x.log.size()).isDone() && asker.log.size() >= 3, 100);
      assertThat(asker.log.get(0)).isEqualTo("1: asked, SyncFuture");
      assertThat(asker.log.get(1)).isEqualTo("1: not yet");
      assertThat(asker.log.get(2)).matches("\\d+: got 42");
      assertThat(asker.log.get(2)).doesNotStartWith("1:");
    }
  }

  @Test
  void replyBetweenReactiveObjectsTakesOneInstantEachWay() {
    try (ManualClock clock = Clock.manual(Duration.ofMillis(1));
        ActiveRuntime rt = ActiveRuntime.builder().jmx(false).build()) {
      ActiveObject<Oracle> oracle = rt.spawn(new Oracle(), ObjectConfig.synchronous(clock));
      Asker asker = new Asker(oracle);
      rt.spawn(asker, ObjectConfig.synchronous(clock));
      clock.step(4);
      // asked at 1, processed by the oracle at 2, the FutureEvent taken by the asker at 3.
      assertThat(asker.log)
          .containsExactly(
              "1: asked, SyncFuture",
              "1: not yet",
              "3: got 42",
              "4: asked, SyncFuture",
              "4: not yet");
    }
  }

  /** A reactive servant that also takes events: it hears its replies as FutureEvents. */
  static final class Listener implements EventProcessor, ReactiveCycle {
    final ActiveRef<Oracle> oracle;
    final List<String> heard = new ArrayList<>();

    Listener(ActiveRef<Oracle> oracle) {
      this.oracle = oracle;
    }

    @Override
    public void process(Event event) {
      if (event instanceof FutureEvent f) {
        heard.add("reply " + f.value() + " from " + f.sender());
      }
    }

    @Override
    public void onCycle(long instant) {
      if (instant == 1) {
        FutureValue<Integer> f = oracle.call(o -> o.answer);
        assertThatThrownBy(() -> f.getValue(Duration.ofSeconds(-1)))
            .isInstanceOf(IllegalArgumentException.class);
      }
    }
  }

  @Test
  void repliesReachAnEventProcessorServantAsFutureEvents() {
    try (ManualClock clock = Clock.manual(Duration.ofMillis(1));
        ActiveRuntime rt = ActiveRuntime.builder().jmx(false).build()) {
      ActiveObject<Oracle> oracle = rt.spawn(new Oracle(), ObjectConfig.synchronous(clock));
      Listener listener = new Listener(oracle);
      rt.spawn(listener, ObjectConfig.synchronous(clock));
      clock.step(3);
      assertThat(listener.heard).containsExactly("reply 42 from " + oracle.address());
    }
  }

  @Test
  void aReactiveObjectStoppedByAnEventTakesNoMoreEventsAndNoCycle() {
    try (ManualClock clock = Clock.manual(Duration.ofMillis(1));
        ActiveRuntime rt = ActiveRuntime.builder().jmx(false).build()) {
      List<String> log = new ArrayList<>();
      final class Quitter implements ReactiveCycle {
        @Override
        public void onCycle(long instant) {
          log.add("cycle " + instant);
        }
      }
      ActiveObject<Quitter> q = rt.spawn(new Quitter(), ObjectConfig.synchronous(clock));
      q.send(x -> log.add("first"));
      q.send(x -> ActiveContext.current().orElseThrow().stop());
      FutureValue<Boolean> third = q.call(x -> log.add("third"));
      clock.step(2);
      assertThat(log).containsExactly("first");
      assertThatThrownBy(() -> third.getValue(Duration.ofSeconds(10)))
          .isInstanceOf(ObjectStoppedException.class);
    }
  }

  @Test
  void aReactiveObjectCannotWaitByNecessity() {
    try (ManualClock clock = Clock.manual(Duration.ofMillis(1));
        ActiveRuntime rt = ActiveRuntime.builder().jmx(false).build()) {
      ActiveObject<Oracle> slow = rt.spawn(new Oracle());
      FutureValue<Integer> fromOutside = slow.callWhen(o -> o.answer < 0, o -> o.answer);
      List<Throwable> failures = new ArrayList<>();
      final class Impatient implements ReactiveCycle {
        @Override
        public void onCycle(long instant) {
          try {
            fromOutside.getValue();
          } catch (IllegalStateException e) {
            failures.add(e);
          }
        }
      }
      rt.spawn(new Impatient(), ObjectConfig.synchronous(clock));
      clock.step();
      assertThat(failures)
          .singleElement()
          .satisfies(e -> assertThat(e).hasMessageContaining("would block its cycle"));
    }
  }

  /** Runs a seeded network of reactive objects and hashes the per-instant trace. */
  private static String traceHash(int workers, int nodes, int instants) throws Exception {
    try (ManualClock clock = Clock.manual(Duration.ofMillis(1));
        ActiveRuntime rt = ActiveRuntime.builder().workers(workers).jmx(false).build()) {
      List<Node> all = new ArrayList<>();
      List<ActiveObject<Node>> refs = new ArrayList<>();
      for (int i = 0; i < nodes; i++) {
        Node n = new Node("n" + i, 1_000 + i);
        all.add(n);
        refs.add(rt.spawn(n, ObjectConfig.synchronous(clock)));
      }
      for (Node n : all) {
        n.peers.addAll(refs);
      }
      clock.step(instants);
      MessageDigest sha = MessageDigest.getInstance("SHA-256");
      for (Node n : all) {
        for (String line : n.log) {
          sha.update((n.name + " " + line + "\n").getBytes(StandardCharsets.UTF_8));
        }
      }
      return HexFormat.of().formatHex(sha.digest());
    }
  }

  @ParameterizedTest
  @ValueSource(ints = {1, 2, 4, 8})
  void manualClockTraceIsIdenticalAcrossRunsAndThreadCounts(int workers) throws Exception {
    String reference = traceHash(1, 12, 60);
    assertThat(traceHash(workers, 12, 60)).isEqualTo(reference);
    assertThat(traceHash(workers, 12, 60)).isEqualTo(reference);
  }

  @Test
  void realTimeClockReleasesPeriodicallyAndMeasuresItself() throws Exception {
    RealTimeClock clock = Clock.realTime(Duration.ofMillis(2));
    try (ActiveRuntime rt = ActiveRuntime.builder().jmx(false).build()) {
      CountDownLatch fifty = new CountDownLatch(50);
      List<Long> instants = new ArrayList<>();
      final class Ticker implements ReactiveCycle {
        @Override
        public void onCycle(long instant) {
          instants.add(instant);
          fifty.countDown();
        }
      }
      ActiveObject<Ticker> t = rt.spawn(new Ticker(), ObjectConfig.synchronous(clock));
      clock.start();
      assertThat(fifty.await(30, TimeUnit.SECONDS)).isTrue();
      t.stop();
      clock.close(); // joins the clock thread: every release is recorded
      ClockStats stats = clock.stats();
      assertThat(stats.instants()).isGreaterThanOrEqualTo(50);
      assertThat(stats.meanPeriod()).isPositive();
      assertThat(stats.jitterMax()).isGreaterThanOrEqualTo(stats.jitterP99());
      assertThat(stats.jitterP99()).isGreaterThanOrEqualTo(stats.jitterP50());
      // Instant numbers only grow; skipped ones are overruns, and counted.
      List<Long> copy;
      synchronized (instants) {
        copy = List.copyOf(instants);
      }
      assertThat(copy).isSorted().doesNotHaveDuplicates();
      long skipped = copy.get(copy.size() - 1) - copy.get(0) + 1 - copy.size();
      assertThat(stats.overruns()).isGreaterThanOrEqualTo(skipped > 0 ? 1 : 0);
    } finally {
      clock.close();
    }
  }

  @Test
  void clocksRefuseNonPositivePeriodsNamingThem() {
    assertThatThrownBy(() -> Clock.manual(Duration.ZERO))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessage("period must be > 0, was PT0S");
    assertThatThrownBy(() -> Clock.realTime(Duration.ofMillis(-5)))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessage("period must be > 0, was PT-0.005S");
  }

  @Test
  void asynchronousConfigTakesNoClockAndSynchronousNeedsOne() {
    try (ManualClock clock = Clock.manual(Duration.ofMillis(1))) {
      assertThatThrownBy(
              () ->
                  new ObjectConfig(
                      Mode.ASYNCHRONOUS,
                      clock,
                      1,
                      OverflowPolicy.reject(),
                      org.armgals.active.spi.ObjectListener.NONE))
          .isInstanceOf(IllegalArgumentException.class)
          .hasMessageContaining("takes no clock");
      assertThatThrownBy(
              () ->
                  new ObjectConfig(
                      Mode.SYNCHRONOUS,
                      null,
                      1,
                      OverflowPolicy.reject(),
                      org.armgals.active.spi.ObjectListener.NONE))
          .isInstanceOf(IllegalArgumentException.class)
          .hasMessageContaining("needs a clock");
    }
  }
}

package org.armgals.active.jms;

import static org.armgals.active.jms.JmsFixture.WAIT;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import org.armgals.active.ActiveException;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.FutureInterruptedException;
import org.armgals.active.FutureTimeoutException;
import org.armgals.active.FutureValue;
import org.armgals.active.Request;
import org.armgals.active.jms.JmsFixture.Sum;
import org.armgals.active.spi.RemoteAnswer;
import org.jspecify.annotations.Nullable;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Who receives the answers from another runtime (decision 0032): the thread waiting for one when it
 * can, the transport's own receiving thread when nobody waits; every answer arrives once, to its
 * own future, however the future is read.
 */
@Timeout(60)
class AnswerReceiverTest {
  static EmbeddedBroker broker;

  @BeforeAll
  static void startBroker() {
    broker = EmbeddedBroker.start();
  }

  @AfterAll
  static void stopBroker() {
    broker.close();
  }

  /** Held until opened: a request that the servant answers only once its gate is open. */
  record Held(@Nullable Address sender, Address destination, int n) implements Request<Integer> {}

  /** Opens the gate. */
  record Open(@Nullable Address sender, Address destination) implements Event {}

  /** Answers sums at once and held requests once opened. */
  static final class Gate implements EventProcessor {
    boolean open;

    @Override
    public boolean isProcessable(Event event) {
      return !(event instanceof Held) || open;
    }

    @Override
    public void process(Event event) {
      if (event instanceof Open) {
        open = true;
      }
    }

    @Override
    public Object answer(Request<?> request) {
      return switch (request) {
        case Sum s -> s.a() + s.b();
        case Held h -> h.n();
        default -> throw new IllegalArgumentException("unexpected " + request);
      };
    }
  }

  /** A runtime that asks ({@code a}) and one that answers ({@code b}), each on its transport. */
  static final class Pair implements AutoCloseable {
    final JmsTransportImpl ta;
    final JmsTransport tb;
    final ActiveRuntime a;
    final ActiveRuntime b;
    final ActiveObject<Gate> gate;
    final ActiveRef<Gate> remote;

    Pair(String prefix) {
      this(prefix, Duration.ofSeconds(30));
    }

    Pair(String prefix, Duration replyTimeout) {
      JmsTransport.Builder builder =
          JmsFixture.transport(broker.inVmUrl())
              .prefix(prefix)
              .allow(Held.class, Open.class)
              .replyTimeout(replyTimeout);
      ta = (JmsTransportImpl) builder.build();
      tb = builder.build();
      a = JmsFixture.runtime("a", ta);
      b = JmsFixture.runtime("b", tb);
      gate = b.spawn(new Gate());
      remote = a.ref(gate.address());
    }

    FutureValue<Integer> sum(int x, int y) {
      return remote.ask(new Sum(null, gate.address(), x, y));
    }

    FutureValue<Integer> held(int n) {
      return remote.ask(new Held(null, gate.address(), n));
    }

    void open() {
      remote.send(new Open(null, gate.address()));
    }

    AnswerReceiver answers() {
      return ta.answers();
    }

    @Override
    public void close() {
      a.close();
      b.close();
      ta.close();
      tb.close();
    }
  }

  /** Waits until {@code condition} holds, looking every 200 µs, for at most {@link #WAIT}. */
  static void await(String what, BooleanSupplier condition) {
    long deadline = System.nanoTime() + WAIT.toNanos();
    while (!condition.getAsBoolean()) {
      if (System.nanoTime() - deadline > 0) {
        throw new AssertionError(what + " not within " + WAIT);
      }
      LockSupport.parkNanos(200_000);
    }
  }

  @Test
  void aCallerWaitingForItsAnswerReceivesItItself() {
    try (Pair p = new Pair("answers-own")) {
      for (int i = 0; i < 50; i++) {
        assertThat(p.sum(i, 1).getValue(WAIT)).isEqualTo(i + 1);
      }
      assertThat(p.answers().receivedByWaiters()).isEqualTo(50);
      assertThat(p.answers().receivedByOwnThread()).isZero();
    }
  }

  @Test
  void anAnswerReadOnlyThroughIsDoneIsReceivedByTheTransportsThread() {
    try (Pair p = new Pair("answers-polled")) {
      FutureValue<Integer> f = p.sum(2, 3);
      await("the answer", f::isDone);
      assertThat(f.getValue(WAIT)).isEqualTo(5);
      assertThat(p.answers().receivedByOwnThread()).isEqualTo(1);
      assertThat(p.answers().receivedByWaiters()).isZero();
    }
  }

  @Test
  void anAnswerFollowedThroughACompletionStageArrives() throws Exception {
    try (Pair p = new Pair("answers-stage")) {
      Integer seven =
          p.sum(3, 4)
              .toCompletionStage()
              .toCompletableFuture()
              .get(WAIT.toMillis(), TimeUnit.MILLISECONDS);
      assertThat(seven).isEqualTo(7);
      assertThat(p.answers().receivedByOwnThread()).isEqualTo(1);
    }
  }

  @Test
  void anAnswerNobodyLooksAtIsReceivedAtALaterSweep() {
    // A short reply timeout sweeps often (every quarter of it), and the sweep nudges the receiver.
    try (Pair p = new Pair("answers-unread", Duration.ofSeconds(2))) {
      FutureValue<Integer> f = p.sum(20, 22);
      await("the answer taken in", () -> ((RemoteAnswer<?>) f).completed());
      assertThat(p.answers().receivedByOwnThread()).isEqualTo(1);
      assertThat(f.getValue(Duration.ZERO)).isEqualTo(42);
    }
  }

  @Test
  void aWaiterWhoseTimeRunsOutLeavesItsAnswerToTheTransport() throws Exception {
    try (Pair p = new Pair("answers-late")) {
      FutureValue<Integer> f = p.held(9);
      assertThatThrownBy(() -> f.getValue(Duration.ofMillis(30)))
          .isInstanceOf(FutureTimeoutException.class);
      p.open();
      await("the late answer taken in", () -> ((RemoteAnswer<?>) f).completed());
      assertThat(f.getValue(Duration.ZERO)).isEqualTo(9);
      assertThat(p.answers().receivedByOwnThread()).isEqualTo(1);
    }
  }

  @Test
  void anInterruptedLeaderStopsWaitingAndTheOthersStillGetTheirAnswers() throws Exception {
    try (Pair p = new Pair("answers-interrupt")) {
      FutureValue<Integer> held = p.held(5);
      AtomicReference<@Nullable Throwable> thrown = new AtomicReference<>();
      Thread waiter =
          Thread.ofPlatform()
              .start(
                  () -> {
                    try {
                      held.getValue(WAIT);
                    } catch (RuntimeException e) {
                      thrown.set(e);
                    }
                  });
      await("the waiter leading", () -> p.answers().leader() == waiter);

      waiter.interrupt();
      waiter.join(WAIT.toMillis());

      assertThat(waiter.isAlive()).isFalse();
      assertThat(thrown.get()).isInstanceOf(FutureInterruptedException.class);
      assertThat(p.sum(1, 1).getValue(WAIT)).isEqualTo(2);
      p.open();
      assertThat(held.getValue(WAIT)).isEqualTo(5);
    }
  }

  @Test
  void closingTheTransportReleasesItsLeaderWithAFailure() throws Exception {
    Pair p = new Pair("answers-close");
    try {
      FutureValue<Integer> held = p.held(1);
      AtomicReference<@Nullable Throwable> thrown = new AtomicReference<>();
      Thread waiter =
          Thread.ofPlatform()
              .start(
                  () -> {
                    try {
                      held.getValue();
                    } catch (RuntimeException e) {
                      thrown.set(e);
                    }
                  });
      await("the waiter leading", () -> p.answers().leader() == waiter);

      p.ta.close();
      waiter.join(WAIT.toMillis());

      assertThat(waiter.isAlive()).isFalse();
      assertThat(thrown.get()).isInstanceOf(ActiveException.class).hasMessageContaining("closed");
    } finally {
      p.close();
    }
  }

  @Test
  void manyWaitersOnPlatformAndVirtualThreadsEachGetTheirOwnAnswers() throws Exception {
    int threads = 8;
    int asks = 200;
    try (Pair p = new Pair("answers-many")) {
      Queue<String> wrong = new ConcurrentLinkedQueue<>();
      List<Thread> all = new ArrayList<>();
      for (int t = 0; t < threads; t++) {
        int id = t;
        Runnable asker =
            () -> {
              for (int i = 0; i < asks; i++) {
                int x = id * 100_000 + i;
                FutureValue<Integer> f = p.sum(x, 1);
                // Every third one is read by polling, as a reactive object reads its futures once
                // a cycle (spinning virtual threads would hold the carriers the servant needs).
                if (i % 3 == 0) {
                  while (!f.isDone()) {
                    LockSupport.parkNanos(100_000);
                  }
                }
                int got = f.getValue(WAIT);
                if (got != x + 1) {
                  wrong.add("thread " + id + " asked " + x + " + 1, got " + got);
                }
              }
            };
        all.add(id % 2 == 0 ? Thread.ofPlatform().start(asker) : Thread.ofVirtual().start(asker));
      }
      for (Thread t : all) {
        t.join(WAIT.toMillis() * 3);
        assertThat(t.isAlive()).as("asker %s done", t).isFalse();
      }

      assertThat(wrong).isEmpty();
      AnswerReceiver r = p.answers();
      assertThat(r.receivedByWaiters() + r.receivedByOwnThread()).isEqualTo((long) threads * asks);
      assertThat(r.receivedByWaiters()).isPositive();
      assertThat(p.ta.awaitedAnswers()).isZero();
    }
  }
}

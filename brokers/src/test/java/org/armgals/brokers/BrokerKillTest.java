package org.armgals.brokers;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import org.armgals.active.ActiveException;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.FutureValue;
import org.armgals.active.Request;
import org.armgals.active.TimeSource;
import org.armgals.active.TransportStats;
import org.armgals.active.jms.JmsTransport;
import org.armgals.brokers.RuntimeNode.Ping;
import org.armgals.brokers.RuntimeNode.Sum;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * A standalone broker killed (SIGKILL) and started again while runtime {@code a} sends events and
 * requests to runtime {@code b} at a steady pace, for both guarantees. At most once (a broker
 * without a journal): on each route, what the sender counted sent is, at the receiver, received or
 * counted lost, exactly; what the sender could not queue is counted unsent. At least once (a broker
 * with a journal): nothing is lost and nothing reaches the object twice: it sees the events
 * numbered 1 to n, each once, in order, and every request is answered. Each run prints its figures
 * on one {@code kill-test} line (docs/benchmarks-broker.md).
 */
class BrokerKillTest {
  private static final Duration WAIT = Duration.ofSeconds(90);
  private static final long PACE_NANOS = 500_000;
  private static final int ASK_EVERY = 50;

  @RegisterExtension static final BrokerExtension PLAIN = BrokerExtension.standalone("kill-amo");

  @RegisterExtension
  static final BrokerExtension JOURNALED = BrokerExtension.standalonePersistent("kill-alo");

  /** Records the numbers of the pings it processes; answers sums. */
  static final class Recorder implements EventProcessor {
    final List<Long> seen = new ArrayList<>();

    @Override
    public void process(Event event) {
      seen.add(((Ping) event).n());
    }

    @Override
    public Object answer(Request<?> request) {
      Sum s = (Sum) request;
      return s.a() + s.b();
    }
  }

  /** What one run saw. */
  record Outcome(
      long calls,
      long pings,
      List<FutureValue<Integer>> asks,
      List<Integer> expected,
      List<Long> seen,
      TransportStats a,
      TransportStats b,
      long outageNanos,
      long longestCallNanos) {

    long answered() {
      long n = 0;
      for (int i = 0; i < asks.size(); i++) {
        try {
          if (asks.get(i).getValue(Duration.ZERO).equals(expected.get(i))) {
            n++;
          }
        } catch (ActiveException failed) {
          // counted as failed
        }
      }
      return n;
    }

    String line(String guarantee) {
      return String.format(
          Locale.ROOT,
          "kill-test guarantee=%s calls=%d sent=%d unsent=%d received=%d lost=%d duplicates=%d"
              + " rejected=%d asks=%d answered=%d outage_ms=%d longest_call_us=%d",
          guarantee,
          calls,
          a.sent(),
          a.unsent(),
          b.received(),
          b.lost(),
          b.duplicates(),
          b.rejected(),
          asks.size(),
          answered(),
          outageNanos / 1_000_000,
          longestCallNanos / 1_000);
    }
  }

  private static void await(String what, BooleanSupplier condition) {
    await(what, condition, () -> "");
  }

  private static void await(
      String what, BooleanSupplier condition, java.util.function.Supplier<String> state) {
    TimeSource time = TimeSource.system();
    long deadline = time.nanoTime() + WAIT.toNanos();
    while (!condition.getAsBoolean()) {
      if (time.nanoTime() - deadline > 0) {
        throw new AssertionError(what + " within " + WAIT + state.get());
      }
      LockSupport.parkNanos(10_000_000);
    }
  }

  /** Sends, kills the broker, starts it again, sends on, then lets both routes settle. */
  private static Outcome run(BrokerExtension brokers, String prefix, boolean atLeastOnce)
      throws Exception {
    StandaloneBroker broker = brokers.broker();
    JmsTransport.Builder builder =
        RuntimeNode.transport(
                broker.url(), broker.spec().user().user(), broker.spec().user().password(), prefix)
            .brokerOption("retryInterval", "100")
            .replyTimeout(atLeastOnce ? WAIT : Duration.ofSeconds(3));
    if (atLeastOnce) {
      builder.guarantee(JmsTransport.Guarantee.AT_LEAST_ONCE, Ping.class, Sum.class);
    }
    TimeSource time = TimeSource.system();
    try (JmsTransport ta = builder.build();
        JmsTransport tb = builder.build();
        ActiveRuntime a = RuntimeNode.runtime("a", ta);
        ActiveRuntime b = RuntimeNode.runtime("b", tb)) {
      ActiveObject<Recorder> recorder = b.spawn(new Recorder());
      Address at = recorder.address();
      ActiveRef<Recorder> remote = a.ref(at);
      List<FutureValue<Integer>> asks = new ArrayList<>();
      List<Integer> expected = new ArrayList<>();
      AtomicLong killedAt = new AtomicLong(Long.MAX_VALUE);
      AtomicLong recoveredAt = new AtomicLong(Long.MAX_VALUE);
      AtomicLong longest = new AtomicLong();
      AtomicLong pings = new AtomicLong();
      AtomicLong calls = new AtomicLong();
      java.util.concurrent.atomic.AtomicBoolean stop =
          new java.util.concurrent.atomic.AtomicBoolean();
      Thread sender =
          Thread.ofPlatform()
              .name("kill-test-sender")
              .start(
                  () -> {
                    while (!stop.get()) {
                      long n = pings.incrementAndGet();
                      long start = time.nanoTime();
                      remote.send(new Ping(null, at, n));
                      calls.incrementAndGet();
                      if (n % ASK_EVERY == 0) {
                        asks.add(remote.ask(new Sum(null, at, (int) n, 1)));
                        expected.add((int) n + 1);
                        calls.incrementAndGet();
                      }
                      long took = time.nanoTime() - start;
                      if (start - killedAt.get() >= 0 && recoveredAt.get() - start > 0) {
                        longest.accumulateAndGet(took, Math::max);
                      }
                      LockSupport.parkNanos(PACE_NANOS);
                    }
                  });
      try {
        await("2,000 events before the kill", () -> tb.stats().received() >= 2_000);
        killedAt.set(time.nanoTime());
        broker.kill();
        broker.start(BrokerExtension.START_TIMEOUT);
        long atRestart = tb.stats().received();
        await("events after the restart", () -> tb.stats().received() > atRestart);
        recoveredAt.set(time.nanoTime());
        await("2,000 events after the restart", () -> tb.stats().received() >= atRestart + 2_000);
      } finally {
        stop.set(true);
        sender.join();
      }
      // One more of each, so that a loss at the end of a route shows as a gap.
      long last = pings.incrementAndGet();
      remote.send(new Ping(null, at, last));
      int lastSum = remote.ask(new Sum(null, at, 1, 1)).getValue(WAIT);
      assertThat(lastSum).isEqualTo(2);
      calls.addAndGet(2);
      await(
          "every event and request of route a->b accounted for at b",
          () -> {
            TransportStats sa = ta.stats();
            TransportStats sb = tb.stats();
            return sb.received() + sb.lost() + sb.rejected() == sa.sent();
          },
          () -> ": a " + ta.stats() + ", b " + tb.stats());
      await(
          "every answer of route b->a accounted for at a",
          () -> {
            TransportStats sa = ta.stats();
            TransportStats sb = tb.stats();
            return sa.received() + sa.lost() + sa.unmatched() == sb.sent();
          },
          () -> ": a " + ta.stats() + ", b " + tb.stats());
      for (FutureValue<Integer> f : asks) {
        try {
          f.getValue(WAIT);
        } catch (ActiveException failed) {
          // a request lost at most once fails at its reply timeout
        }
      }
      List<Long> seen = recorder.call(r -> List.copyOf(r.seen)).getValue(WAIT);
      return new Outcome(
          calls.get(),
          last,
          List.copyOf(asks),
          List.copyOf(expected),
          seen,
          ta.stats(),
          tb.stats(),
          recoveredAt.get() - killedAt.get(),
          longest.get());
    }
  }

  @Test
  void atMostOnceEverythingSentIsReceivedOrCountedLostAcrossABrokerKill() throws Exception {
    Outcome o = run(PLAIN, "kill-amo", false);
    System.out.println(o.line("amo"));

    assertThat(o.a().sent() + o.a().unsent()).isEqualTo(o.calls());
    assertThat(o.b().received() + o.b().lost()).isEqualTo(o.a().sent());
    assertThat(o.b().rejected()).isZero();
    assertThat(o.b().duplicates()).isZero();
    assertThat(o.a().rejected()).isZero();
    assertThat(o.seen()).isSorted().doesNotHaveDuplicates();
    long requestsReceived = o.b().received() - o.seen().size();
    assertThat(requestsReceived).isBetween(0L, (long) o.asks().size() + 1);
    assertThat(o.asks()).allSatisfy(f -> assertThat(f.isDone()).isTrue());
  }

  @Test
  void atLeastOnceNothingIsLostAndNothingDeliveredTwiceAcrossABrokerKill() throws Exception {
    Outcome o = run(JOURNALED, "kill-alo", true);
    System.out.println(o.line("alo"));

    List<Long> all = new ArrayList<>();
    for (long n = 1; n <= o.pings(); n++) {
      all.add(n);
    }
    assertThat(o.seen()).isEqualTo(all);
    assertThat(o.a().unsent()).isZero();
    assertThat(o.a().sent()).isEqualTo(o.calls());
    assertThat(o.b().lost()).isZero();
    assertThat(o.b().rejected()).isZero();
    assertThat(o.b().received()).isEqualTo(o.a().sent());
    assertThat(o.a().lost()).isZero();
    assertThat(o.answered()).isEqualTo(o.asks().size());
  }
}

package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/**
 * {@link ActiveObject#stop()} racing with synchronized requests on a real runtime: in each round
 * several callers fire requests at a fresh object while another thread stops it at a random moment.
 * Every request must end one way or the other, never hang: refused at the door, completed with its
 * value, or failed with {@link ObjectStoppedException}. A request still pending after {@link
 * #PATIENCE} counts as hung.
 */
class StopRaceStressTest {
  private static final int ROUNDS = 300;
  private static final int CALLERS = 3;
  private static final int CALLS_PER_CALLER = 40;
  private static final Duration PATIENCE = Duration.ofSeconds(10);

  /** Numbers the requests it processes. */
  static final class Numberer {
    final AtomicInteger processed = new AtomicInteger();

    int next() {
      return processed.incrementAndGet();
    }
  }

  /** What the callers of one run saw. */
  static final class Outcomes {
    final ConcurrentLinkedQueue<Integer> values = new ConcurrentLinkedQueue<>();
    final AtomicInteger refused = new AtomicInteger();
    final AtomicInteger cancelled = new AtomicInteger();
    final ConcurrentLinkedQueue<String> hung = new ConcurrentLinkedQueue<>();
    final ConcurrentLinkedQueue<Throwable> unexpected = new ConcurrentLinkedQueue<>();
  }

  @Test
  void everySynchronizedRequestRacingStopCompletesOrFailsWithObjectStopped()
      throws InterruptedException {
    Outcomes all = new Outcomes();
    int processed = 0;
    try (LiveRuntime live = new LiveRuntime("stop-race")) {
      for (int round = 0; round < ROUNDS; round++) {
        Numberer numberer = new Numberer();
        ActiveObject<Numberer> object = live.spawn(numberer, ObjectConfig.asynchronous());
        Outcomes outcomes = new Outcomes();
        raceStop(object, outcomes);
        processed += numberer.processed.get();

        assertThat(outcomes.hung).as("requests pending %s after stop", PATIENCE).isEmpty();
        assertThat(outcomes.unexpected).isEmpty();
        List<Integer> values = new ArrayList<>(outcomes.values);
        Set<Integer> distinct = new HashSet<>(values);
        assertThat(distinct).as("values returned in round %d", round).hasSize(values.size());
        assertThat(values.size())
            .as("requests processed vs completed with a value in round %d", round)
            .isEqualTo(numberer.processed.get());
        assertThat(values.size() + outcomes.refused.get() + outcomes.cancelled.get())
            .as("requests completed + refused + cancelled in round %d", round)
            .isEqualTo(CALLERS * CALLS_PER_CALLER);
        assertThat(object.isStopped()).isTrue();
        awaitEmpty(object);
        all.refused.addAndGet(outcomes.refused.get());
        all.cancelled.addAndGet(outcomes.cancelled.get());
        all.values.addAll(outcomes.values);
      }
      assertThat(List.of(all.values.size(), all.refused.get(), all.cancelled.get()))
          .as("completed, refused, cancelled over all rounds: each outcome must occur")
          .allMatch(n -> n > 0);
      RuntimeStats stats = live.runtime().stats();
      assertThat(stats.processed()).isEqualTo(processed);
      assertThat(stats.rejected()).as("requests refused at the door").isEqualTo(all.refused.get());
      assertThat(stats.objects()).isZero();
      assertThat(live.failures()).isEmpty();
    }
  }

  /** Runs one round: the callers and a stopper start together; returns once all are done. */
  private static void raceStop(ActiveObject<Numberer> object, Outcomes outcomes)
      throws InterruptedException {
    CountDownLatch start = new CountDownLatch(1);
    List<Thread> threads = new ArrayList<>();
    for (int c = 0; c < CALLERS; c++) {
      threads.add(Thread.ofPlatform().start(() -> call(object, start, outcomes)));
    }
    int delay = ThreadLocalRandom.current().nextInt(2_000);
    threads.add(
        Thread.ofPlatform()
            .start(
                () -> {
                  awaitQuietly(start);
                  for (int i = 0; i < delay; i++) {
                    Thread.onSpinWait();
                  }
                  object.stop();
                }));
    start.countDown();
    for (Thread t : threads) {
      t.join();
    }
  }

  private static void call(ActiveObject<Numberer> object, CountDownLatch start, Outcomes outcomes) {
    awaitQuietly(start);
    List<FutureValue<Integer>> futures = new ArrayList<>();
    for (int i = 0; i < CALLS_PER_CALLER; i++) {
      try {
        futures.add(object.call(Numberer::next));
      } catch (ObjectStoppedException e) {
        outcomes.refused.incrementAndGet();
      }
    }
    for (FutureValue<Integer> f : futures) {
      try {
        outcomes.values.add(f.getValue(PATIENCE));
      } catch (ObjectStoppedException e) {
        outcomes.cancelled.incrementAndGet();
      } catch (FutureTimeoutException e) {
        outcomes.hung.add(f.toString());
      } catch (RuntimeException e) {
        outcomes.unexpected.add(e);
      }
    }
  }

  private static void awaitQuietly(CountDownLatch latch) {
    try {
      latch.await();
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new IllegalStateException("interrupted before the round started", e);
    }
  }

  /**
   * The depth of a buffer counts, for a short while, events its running activation has already
   * taken (see {@link ActiveObject#queueDepth()}); once the object's last activation is over it
   * must reach zero.
   */
  private static void awaitEmpty(ActiveObject<?> object) {
    long deadline = TimeSource.system().nanoTime() + PATIENCE.toNanos();
    while (object.queueDepth() != 0) {
      if (TimeSource.system().nanoTime() - deadline > 0) {
        throw new AssertionError(
            object.address() + " still counts " + object.queueDepth() + " queued events");
      }
      Thread.onSpinWait();
    }
  }
}

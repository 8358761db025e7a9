package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BiConsumer;
import org.armgals.active.InboundAnswerTest.Capture;
import org.jspecify.annotations.Nullable;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Workers learn the pace of requests from another runtime (decision 0033): when such requests keep
 * waking a worker sooner than its longest spin after it parked, the workers spin long enough to
 * find the next ones without a wake-up. Requests from the runtime's own callers at the same pace
 * keep the short spin. The asker here parks while it waits, as a thread waiting for an answer from
 * another runtime does, so that the machine's cores are free for the spin.
 */
@Timeout(60)
class InboundPaceTest {
  private static final int WARM_UP = 200;
  private static final int MEASURED = 300;

  /** A pause between two requests: longer than the shortest spin, shorter than the longest. */
  private static final long PACE_NANOS = 50_000;

  record Ping(@Nullable Address sender, Address destination, int n) implements Request<Integer> {}

  static final class Echo implements EventProcessor {
    @Override
    public void process(Event event) {}

    @Override
    public Object answer(Request<?> request) {
      return ((Ping) request).n();
    }
  }

  /** Asks {@code n} and parks until the answer is in; returns it. */
  private interface Asker {
    void ask(int n, BiConsumer<@Nullable Object, @Nullable Throwable> answer);
  }

  private static long wakeUpsOverMeasuredRequests(ActiveRuntime rt, Asker asker)
      throws InterruptedException {
    Dispatcher dispatcher = ((RuntimeImpl) rt).dispatcher();
    long before = 0;
    for (int i = 0; i < WARM_UP + MEASURED; i++) {
      if (i == WARM_UP) {
        before = dispatcher.wakeUps();
      }
      CountDownLatch done = new CountDownLatch(1);
      AtomicReference<@Nullable Object> got = new AtomicReference<>();
      asker.ask(
          i,
          (value, failure) -> {
            got.set(failure == null ? value : failure);
            done.countDown();
          });
      assertThat(done.await(10, TimeUnit.SECONDS)).isTrue();
      assertThat(got.get()).isEqualTo(i);
      LockSupport.parkNanos(PACE_NANOS); // the asker's own work between two requests
    }
    return dispatcher.wakeUps() - before;
  }

  @Test
  void requestsFromAnotherRuntimeAtASteadyPaceFindASpinningWorker() throws Exception {
    Capture transport = new Capture();
    try (ActiveRuntime rt =
        ActiveRuntime.builder().name("there").transport(transport).jmx(false).build()) {
      ActiveObject<Echo> echo = rt.spawn(new Echo());
      Asker fromThere =
          (n, answer) ->
              transport.inbound().ask(echo.address(), new Ping(null, echo.address(), n), answer);
      // On a loaded machine the spinning worker may lose its core for longer than the pace, and
      // the request that comes meanwhile wakes a parked one: up to three rounds are run, and the
      // best counts. Without the learned pace every round wakes a worker for nearly each request.
      long bound = MEASURED * 2 / 3;
      List<Long> rounds = new ArrayList<>();
      while (rounds.size() < 3 && (rounds.isEmpty() || rounds.getLast() >= bound)) {
        rounds.add(wakeUpsOverMeasuredRequests(rt, fromThere));
      }

      assertThat(Collections.min(rounds))
          .as("wake-ups over %d requests, per round %s", MEASURED, rounds)
          .isLessThan(bound);
    }
  }

  @Test
  void requestsFromThisRuntimesCallersAtTheSamePaceKeepTheShortSpin() throws Exception {
    try (ActiveRuntime rt = ActiveRuntime.builder().name("alone").jmx(false).build()) {
      ActiveObject<Echo> echo = rt.spawn(new Echo());
      long woken =
          wakeUpsOverMeasuredRequests(
              rt,
              (n, answer) ->
                  echo.ask(new Ping(null, echo.address(), n))
                      .toCompletionStage()
                      .whenComplete(answer));

      assertThat(woken).as("wake-ups over %d requests", MEASURED).isGreaterThan(MEASURED * 9 / 10);
    }
  }
}

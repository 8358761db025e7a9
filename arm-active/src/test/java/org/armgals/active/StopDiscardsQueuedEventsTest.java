package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowable;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/**
 * {@link ActiveObject#stop()} discards the events still queued, even those queued behind an event
 * that is being processed when stop() is called: the activation looks at STOPPED between events.
 * The deterministic form of what {@link StopRaceStressTest} checks under races.
 */
class StopDiscardsQueuedEventsTest {
  private static final Duration PATIENCE = Duration.ofSeconds(10);

  @Test
  void requestsQueuedBehindTheRunningOneFailWithObjectStoppedOnceStopReturns() throws Exception {
    try (LiveRuntime live = new LiveRuntime("stop-discards")) {
      CountDownLatch running = new CountDownLatch(1);
      CountDownLatch release = new CountDownLatch(1);
      AtomicInteger startedAfterStop = new AtomicInteger();
      AtomicInteger stopReturned = new AtomicInteger();
      ActiveObject<Object> object = live.spawn(new Object(), ObjectConfig.asynchronous());

      FutureValue<String> first =
          object.call(
              s -> {
                running.countDown();
                release.await();
                return "first";
              });
      running.await();
      List<FutureValue<Integer>> queued = new ArrayList<>();
      for (int i = 0; i < 3; i++) {
        queued.add(
            object.call(
                s -> {
                  if (stopReturned.get() != 0) {
                    startedAfterStop.incrementAndGet();
                  }
                  return 0;
                }));
      }
      object.stop();
      stopReturned.set(1);
      release.countDown();

      assertThat(first.getValue(PATIENCE)).isEqualTo("first");
      for (FutureValue<Integer> f : queued) {
        assertThat(catchThrowable(() -> f.getValue(PATIENCE)))
            .as("a request queued when stop() was called")
            .isInstanceOf(ObjectStoppedException.class);
      }
      assertThat(startedAfterStop).as("requests that started after stop() returned").hasValue(0);
    }
  }

  @Test
  void anObjectThatStopsItselfLeavesTheRuntimeAndFailsWhatIsQueuedBehind() throws Exception {
    try (LiveRuntime live = new LiveRuntime("stop-itself")) {
      CountDownLatch release = new CountDownLatch(1);
      ActiveObject<Object> object = live.spawn(new Object(), ObjectConfig.asynchronous());
      Address address = object.address();

      FutureValue<String> last =
          object.call(
              s -> {
                release.await();
                ActiveContext.current().orElseThrow().stop();
                return "stopped itself";
              });
      FutureValue<Integer> behind = object.call(s -> 1);
      release.countDown();

      assertThat(last.getValue(PATIENCE)).isEqualTo("stopped itself");
      assertThat(catchThrowable(() -> behind.getValue(PATIENCE)))
          .as("a request queued behind the one that stopped the object")
          .isInstanceOf(ObjectStoppedException.class);
      assertThat(object.isStopped()).isTrue();
      assertThat(object.queueDepth()).isZero();
      assertThat(catchThrowable(() -> live.runtime().ref(address)))
          .as("the runtime's table no longer holds it")
          .isInstanceOf(ObjectStoppedException.class);
      assertThat(catchThrowable(() -> object.send(s -> {})))
          .isInstanceOf(ObjectStoppedException.class);
    }
  }
}

package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The futures a transport completes with an answer from another runtime (decision 0030). */
class RemoteFutureTest {

  @Test
  @Timeout(30)
  void aWaiterForAnAnswerFromAnotherRuntimeParksAtOnceWithoutSpinning() throws Exception {
    // Frozen time: a waiter that spun until its spin ended would never park.
    ValueFuture<String> f = ValueFuture.remote("b/1", () -> 0L, null);
    AtomicReference<String> got = new AtomicReference<>();
    Thread waiter = Thread.ofPlatform().start(() -> got.set(f.getValue()));
    while (waiter.getState() != Thread.State.WAITING || LockSupport.getBlocker(waiter) != f) {
      Thread.onSpinWait(); // bounded by the test's timeout
    }
    f.complete("answer");
    waiter.join();
    assertThat(got.get()).isEqualTo("answer");
  }

  @Test
  @Timeout(30)
  void theWaitOfAnAnswerTimesOutOnTheTransportsTime() {
    AtomicLong now = new AtomicLong();
    ValueFuture<String> f =
        ValueFuture.remote("b/1", () -> now.addAndGet(Duration.ofMillis(10).toNanos()), null);
    assertThatThrownBy(() -> f.getValue(Duration.ofMillis(50)))
        .isInstanceOf(FutureTimeoutException.class)
        .hasMessageContaining("b/1");
    assertThat(now.get()).isGreaterThanOrEqualTo(Duration.ofMillis(50).toNanos());
  }
}

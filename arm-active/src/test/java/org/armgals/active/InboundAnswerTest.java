package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import org.armgals.active.spi.Transport;
import org.jspecify.annotations.Nullable;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The runtime's inbound side as a transport sees it: a request from another runtime whose outcome
 * goes to a callback, called on the thread that completes the request.
 */
@Timeout(30)
class InboundAnswerTest {

  record Twice(@Nullable Address sender, Address destination, int n) implements Request<Integer> {}

  /** Answers {@link Twice}; remembers the thread it answered on; throws on a negative number. */
  static final class Doubler implements EventProcessor {
    volatile @Nullable Thread answeredOn;

    @Override
    public void process(Event event) {}

    @Override
    public Object answer(Request<?> request) {
      answeredOn = Thread.currentThread();
      int n = ((Twice) request).n();
      if (n < 0) {
        throw new IllegalStateException("negative: " + n);
      }
      return 2 * n;
    }
  }

  /** A transport that only keeps the inbound side the runtime attaches, for the test to call. */
  static final class Capture implements Transport {
    final AtomicReference<Transport.@Nullable Inbound> inbound = new AtomicReference<>();

    @Override
    public void attach(String runtime, Inbound in) {
      inbound.set(in);
    }

    @Override
    public void detach(String runtime) {}

    @Override
    public void send(Address destination, Event event) {
      throw new UnsupportedOperationException("not in this test");
    }

    Inbound inbound() {
      Inbound in = inbound.get();
      assertThat(in).as("the runtime attached its inbound side").isNotNull();
      return java.util.Objects.requireNonNull(in);
    }
  }

  /** What a callback was given, and on which thread. */
  static final class Outcome {
    final CountDownLatch called = new CountDownLatch(1);
    final List<String> calls = new ArrayList<>();
    volatile @Nullable Object value;
    volatile @Nullable Throwable failure;
    volatile @Nullable Thread thread;

    void accept(@Nullable Object v, @Nullable Throwable f) {
      synchronized (calls) {
        calls.add(v + "/" + f);
      }
      value = v;
      failure = f;
      thread = Thread.currentThread();
      called.countDown();
    }

    void await() throws InterruptedException {
      assertThat(called.await(10, TimeUnit.SECONDS)).as("the answer callback ran").isTrue();
    }
  }

  private static ActiveRuntime runtime(Capture transport) {
    return ActiveRuntime.builder().name("here").jmx(false).transport(transport).build();
  }

  @Test
  void theAnswerRunsOnTheThreadThatCompletesTheRequest() throws Exception {
    Capture transport = new Capture();
    try (ActiveRuntime rt = runtime(transport)) {
      Doubler servant = new Doubler();
      ActiveObject<Doubler> doubler = rt.spawn(servant);
      Outcome outcome = new Outcome();

      transport
          .inbound()
          .ask(doubler.address(), new Twice(null, doubler.address(), 21), outcome::accept);

      outcome.await();
      assertThat(outcome.value).isEqualTo(42);
      assertThat(outcome.failure).isNull();
      assertThat(outcome.thread).isNotNull().isSameAs(servant.answeredOn);
      assertThat(outcome.thread).isNotSameAs(Thread.currentThread());
    }
  }

  @Test
  void aServantsFailureReachesTheAnswerWithItsCause() throws Exception {
    Capture transport = new Capture();
    try (ActiveRuntime rt = runtime(transport)) {
      ActiveObject<Doubler> doubler = rt.spawn(new Doubler());
      Outcome outcome = new Outcome();

      transport
          .inbound()
          .ask(doubler.address(), new Twice(null, doubler.address(), -1), outcome::accept);

      outcome.await();
      assertThat(outcome.value).isNull();
      assertThat(outcome.failure)
          .isInstanceOf(IllegalStateException.class)
          .hasMessage("negative: -1");
      assertThat(outcome.calls).hasSize(1);
    }
  }

  @Test
  void aRequestToAStoppedObjectIsRefusedAndNeverAnswered() {
    Capture transport = new Capture();
    try (ActiveRuntime rt = runtime(transport)) {
      ActiveObject<Doubler> doubler = rt.spawn(new Doubler());
      doubler.stop();
      Outcome outcome = new Outcome();

      assertThatThrownBy(
              () ->
                  transport
                      .inbound()
                      .ask(
                          doubler.address(),
                          new Twice(null, doubler.address(), 1),
                          outcome::accept))
          .isInstanceOf(ObjectStoppedException.class);
      assertThat(outcome.calls).isEmpty();
    }
  }

  @Test
  void aDroppedRequestIsAnsweredWithTheDrop() throws Exception {
    Capture transport = new Capture();
    try (ActiveRuntime rt = runtime(transport)) {
      ActiveObject<Doubler> doubler =
          rt.spawn(
              new Doubler(),
              ObjectConfig.asynchronous()
                  .withCapacity(1)
                  .withOverflow(OverflowPolicy.dropNewest()));
      CountDownLatch release = new CountDownLatch(1);
      CountDownLatch busy = new CountDownLatch(1);
      doubler.send(
          d -> {
            busy.countDown();
            release.await();
          });
      assertThat(busy.await(10, TimeUnit.SECONDS)).isTrue();
      doubler.send(d -> {}); // fills the one place
      Outcome outcome = new Outcome();

      transport
          .inbound()
          .ask(doubler.address(), new Twice(null, doubler.address(), 1), outcome::accept);

      outcome.await();
      release.countDown();
      assertThat(outcome.value).isNull();
      assertThat(outcome.failure).isInstanceOf(BufferFullException.class);
      assertThat(outcome.calls).hasSize(1);
      assertThat(rt.shutdown(ShutdownMode.DRAIN, Duration.ofSeconds(10))).isTrue();
    }
  }
}

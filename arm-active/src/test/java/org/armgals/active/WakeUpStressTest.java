package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicIntegerArray;
import org.junit.jupiter.api.Test;

/**
 * The idle/wake-up protocol on a real runtime, at high iteration counts: each sender sends one
 * event and waits until it is processed before sending the next, so most events arrive just as the
 * object finishes its previous activation and goes idle, the moment a missing re-check after
 * clearing SCHEDULED would strand them. A stranded event is reported after {@link #PATIENCE}.
 */
class WakeUpStressTest {
  private static final int SENDERS = 2;
  private static final int EVENTS_PER_SENDER = 25_000;
  private static final Duration PATIENCE = Duration.ofSeconds(10);

  /** Counts, per sending thread, the events processed; readable from any thread. */
  static final class Progress implements EventProcessor {
    final AtomicIntegerArray processed = new AtomicIntegerArray(SENDERS);

    @Override
    public void process(Event event) {
      Tagged t = (Tagged) event;
      if (processed.get(t.thread()) + 1 != t.seq()) {
        throw new IllegalStateException(
            "thread " + t.thread() + ": got event " + t.seq() + " after " + processed);
      }
      processed.set(t.thread(), t.seq());
    }
  }

  @Test
  void anEventSentWhileTheObjectGoesIdleIsAlwaysProcessed() throws InterruptedException {
    ConcurrentLinkedQueue<Throwable> errors = new ConcurrentLinkedQueue<>();
    try (LiveRuntime live = new LiveRuntime("wake-up")) {
      Progress progress = new Progress();
      ActiveObject<Progress> object = live.spawn(progress, ObjectConfig.asynchronous());
      List<Thread> senders = new ArrayList<>();
      for (int s = 0; s < SENDERS; s++) {
        int thread = s;
        senders.add(
            Thread.ofPlatform()
                .name("sender-" + s)
                .start(
                    () -> {
                      try {
                        pingPong(object, progress, thread);
                      } catch (Throwable e) {
                        errors.add(e);
                      }
                    }));
      }
      for (Thread t : senders) {
        t.join();
      }
      assertThat(errors).isEmpty();
      assertThat(live.failures()).isEmpty();
      assertThat(object.queueDepth()).isZero();
    }
  }

  private static void pingPong(ActiveObject<Progress> object, Progress progress, int thread) {
    for (int seq = 1; seq <= EVENTS_PER_SENDER; seq++) {
      object.send(new Tagged(object.address(), thread, seq));
      long deadline = TimeSource.system().nanoTime() + PATIENCE.toNanos();
      while (progress.processed.get(thread) < seq) {
        if (TimeSource.system().nanoTime() - deadline > 0) {
          throw new AssertionError(
              "lost wake-up: event "
                  + seq
                  + " of sender "
                  + thread
                  + " not processed after "
                  + PATIENCE
                  + "; queue depth "
                  + object.queueDepth());
        }
        Thread.onSpinWait();
      }
    }
  }
}

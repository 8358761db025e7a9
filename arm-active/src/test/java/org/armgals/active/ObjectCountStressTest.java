package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ThreadLocalRandom;
import org.junit.jupiter.api.Test;

/**
 * The object table counts no objects: {@code stats().objects()} is computed from the numbers handed
 * out and the removals each chunk counts, and chunks are freed as their last object stops (decision
 * 0059). Several threads create objects and stop most of them at once, across many chunks; once
 * they are done, the count is exactly the objects left, each of them still found by its address,
 * and zero after those stop too.
 */
class ObjectCountStressTest {
  private static final int THREADS = 4;
  private static final int OBJECTS_PER_THREAD = 6 * ObjectTable.CHUNK;

  @Test
  void theCountIsExactOnceCreatorsAndStoppersAreDone() throws InterruptedException {
    try (LiveRuntime live = new LiveRuntime("object-count")) {
      ActiveRuntime rt = live.runtime();
      List<List<ActiveObject<Object>>> kept = new ArrayList<>();
      List<Thread> threads = new ArrayList<>();
      CountDownLatch start = new CountDownLatch(1);
      for (int t = 0; t < THREADS; t++) {
        List<ActiveObject<Object>> mine = new ArrayList<>();
        kept.add(mine);
        threads.add(
            Thread.ofPlatform()
                .start(
                    () -> {
                      awaitQuietly(start);
                      ThreadLocalRandom random = ThreadLocalRandom.current();
                      for (int i = 0; i < OBJECTS_PER_THREAD; i++) {
                        ActiveObject<Object> o = rt.spawn(new Object());
                        if (random.nextInt(10) == 0) {
                          mine.add(o);
                        } else if (random.nextBoolean()) {
                          o.stop();
                        } else {
                          o.send(s -> ActiveContext.current().ifPresent(ActiveObject::stop));
                        }
                      }
                    }));
      }
      start.countDown();
      for (Thread t : threads) {
        t.join();
      }
      List<ActiveObject<Object>> left = kept.stream().flatMap(List::stream).toList();
      long deadline = System.nanoTime() + 10_000_000_000L;
      // The objects that stop themselves do so on the workers: wait until they all have.
      while (rt.stats().objects() != left.size() && System.nanoTime() - deadline < 0) {
        Thread.onSpinWait();
      }
      assertThat(rt.stats().objects()).isEqualTo(left.size());
      for (ActiveObject<Object> o : left) {
        assertThat(rt.ref(o.address())).isSameAs(o);
      }
      left.forEach(ActiveObject::stop);
      assertThat(rt.stats().objects()).isZero();
      assertThat(live.failures()).isEmpty();
    }
  }

  private static void awaitQuietly(CountDownLatch latch) {
    try {
      latch.await();
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }
}

package org.armgals.active;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicIntegerArray;
import org.junit.jupiter.api.Test;

/**
 * The run queue's contract: objects come out once each, in the order they went in, and an object
 * taken out may go in again at once and comes out again in its new place, through the queue running
 * dry (its stub going back in) and refilling, with one thread queueing or several.
 */
class RunQueueTest {
  private final HandDrivenRuntime runtime = new HandDrivenRuntime();

  private List<Core<?>> objects(int n) {
    List<Core<?>> objects = new ArrayList<>(n);
    for (int i = 0; i < n; i++) {
      objects.add(runtime.spawn(new Object(), ObjectConfig.asynchronous()));
    }
    return objects;
  }

  @Test
  void anObjectTakenOutAndQueuedAgainComesOutOnceInItsNewPlace() {
    List<Core<?>> o = objects(3);
    Core<?> a = o.get(0);
    Core<?> b = o.get(1);
    Core<?> c = o.get(2);
    RunQueue q = new RunQueue();

    q.offer(a);
    assertThat(q.poll()).isSameAs(a); // the queue runs dry: its stub goes back in behind a
    assertThat(q.poll()).isNull();
    q.offer(b);
    q.offer(a);
    q.offer(c);
    assertThat(q.poll()).isSameAs(b);
    q.offer(b); // queued again while a and c wait
    assertThat(q.poll()).isSameAs(a);
    assertThat(q.poll()).isSameAs(c);
    assertThat(q.poll()).isSameAs(b);
    assertThat(q.poll()).isNull();
    assertThat(q.isEmpty()).isTrue();
    q.offer(c);
    assertThat(q.isEmpty()).isFalse();
    assertThat(q.poll()).isSameAs(c);
    assertThat(q.poll()).isNull();
  }

  @Test
  void aNodeLeavesTheQueueWithNoLinkTheStubToo() {
    List<Core<?>> o = objects(2);
    Core<?> a = o.get(0);
    Core<?> b = o.get(1);
    RunQueue q = new RunQueue();

    q.offer(a);
    assertThat(q.poll()).isSameAs(a); // the stub goes back in, behind a
    assertThat(RunQueue.successorOf(a)).isNull();
    q.offer(b); // links the stub to b
    assertThat(q.poll()).isSameAs(b); // the stub is passed over, then goes back in behind b
    assertThat(RunQueue.successorOf(b)).isNull();
    // A link left in the stub would keep b reachable, and a poll between a producer's exchange and
    // its link would follow it to b.
    assertThat(RunQueue.successorOf(q.stub)).isNull();
  }

  @Test
  void aThousandRandomStepsGiveWhatAPlainQueueGives() {
    List<Core<?>> o = objects(8);
    RunQueue q = new RunQueue();
    ArrayDeque<Core<?>> model = new ArrayDeque<>();
    Random random = new Random(84);
    for (int step = 0; step < 1_000; step++) {
      // Offer an object that is out of the queue, as the runtime does (one SCHEDULED flag each),
      // or poll; the queue often runs dry, so the stub goes round many times.
      List<Core<?>> out = new ArrayList<>(o);
      out.removeAll(model);
      if (!out.isEmpty() && random.nextInt(100) < 55) {
        Core<?> c = out.get(random.nextInt(out.size()));
        q.offer(c);
        model.addLast(c);
      } else {
        assertThat(q.poll()).as("step %d", step).isSameAs(model.pollFirst());
      }
      assertThat(q.isEmpty()).as("step %d", step).isEqualTo(model.isEmpty());
    }
  }

  @Test
  void producersOnThreadsOfTheirOwnLoseAndRepeatNothing() throws InterruptedException {
    int producers = 3;
    int perProducer = 50;
    int rounds = 2_000;
    List<Core<?>> o = objects(producers * perProducer);
    RunQueue q = new RunQueue();
    // 1 while an object is queued: it goes in again only once it has come out, as under its
    // SCHEDULED flag.
    AtomicIntegerArray queued = new AtomicIntegerArray(o.size());
    Map<Core<?>, Integer> index = new IdentityHashMap<>();
    for (int i = 0; i < o.size(); i++) {
      index.put(o.get(i), i);
    }
    ConcurrentLinkedQueue<String> problems = new ConcurrentLinkedQueue<>();
    CountDownLatch finished = new CountDownLatch(producers);
    List<Thread> threads = new ArrayList<>();
    for (int p = 0; p < producers; p++) {
      int first = p * perProducer;
      threads.add(
          Thread.ofPlatform()
              .start(
                  () -> {
                    for (int r = 0; r < rounds; r++) {
                      for (int i = first; i < first + perProducer; i++) {
                        if (queued.compareAndSet(i, 0, 1)) {
                          q.offer(o.get(i));
                        }
                      }
                    }
                    finished.countDown();
                  }));
    }
    long taken = 0;
    Set<Integer> seen = new HashSet<>();
    // A queue that hands out a node twice may link it into a cycle and never run dry: give up then.
    long deadline = TimeSource.system().nanoTime() + TimeUnit.SECONDS.toNanos(30);
    boolean done = false;
    while (!done) {
      if (TimeSource.system().nanoTime() - deadline > 0) {
        problems.add("still taking objects after 30 s, " + taken + " taken");
        break;
      }
      if (finished.getCount() == 0 && q.isEmpty()) {
        done = true; // one more poll, which finds nothing
      }
      Core<?> c = q.poll();
      if (c == null) {
        Thread.onSpinWait();
        continue;
      }
      int i = index.get(c);
      seen.add(i);
      if (!queued.compareAndSet(i, 1, 0)) {
        problems.add("object " + i + " came out while not queued");
      }
      taken++;
    }
    assertThat(problems).isEmpty();
    for (Thread t : threads) {
      assertThat(t.join(Duration.ofSeconds(30))).isTrue();
    }
    assertThat(q.poll()).isNull();
    for (int i = 0; i < o.size(); i++) {
      assertThat(queued.get(i)).as("object %d left in the queue", i).isZero();
    }
    assertThat(seen).hasSize(o.size());
    assertThat(taken).isGreaterThanOrEqualTo(o.size());
  }
}

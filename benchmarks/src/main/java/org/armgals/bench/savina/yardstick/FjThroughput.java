package org.armgals.bench.savina.yardstick;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicInteger;
import org.armgals.bench.savina.Trial;
import org.armgals.bench.savina.Workload;

/**
 * The main thread sends {@code events} events to each of {@code objects} actors, round robin; each
 * counts them and reports when it has had all of its own.
 */
final class FjThroughput implements Workload {
  private final YardstickSuite suite;
  private final int objects;
  private final int events;

  FjThroughput(YardstickSuite suite, int objects, int events) {
    this.suite = suite;
    this.objects = objects;
    this.events = events;
  }

  /** A receiver: counts its events and, at the last one it expects, tells the run. */
  static final class Receiver {
    private final int expected;
    private final AtomicInteger finished;
    private final CompletableFuture<Integer> done;
    private int received;

    Receiver(int expected, AtomicInteger finished, CompletableFuture<Integer> done) {
      this.expected = expected;
      this.finished = finished;
      this.done = done;
    }

    void event() {
      if (++received == expected) {
        int n = finished.decrementAndGet();
        if (n == 0) {
          done.complete(expected);
        }
      }
    }
  }

  @Override
  public Trial prepare() {
    AtomicInteger finished = new AtomicInteger(objects);
    CompletableFuture<Integer> done = new CompletableFuture<>();
    List<Actor<Receiver>> receivers = new ArrayList<>(objects);
    for (int i = 0; i < objects; i++) {
      receivers.add(suite.spawn(new Receiver(events, finished, done)));
    }
    return new Trial() {
      @Override
      public long run() throws InterruptedException {
        for (int e = 0; e < events; e++) {
          for (Actor<Receiver> r : receivers) {
            r.send(Receiver::event);
          }
        }
        // Each receiver counts down once, at exactly its expected count: a lost event hangs the
        // run, and the wait then fails it.
        suite.await(done, "fjthrput");
        return (long) objects * events;
      }

      @Override
      public void close() {}
    };
  }
}

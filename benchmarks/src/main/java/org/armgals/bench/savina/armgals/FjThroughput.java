package org.armgals.bench.savina.armgals;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicInteger;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.bench.savina.Trial;
import org.armgals.bench.savina.Workload;

/**
 * The main thread sends {@code events} one-way events to each of {@code objects} objects, round
 * robin; each object counts them and reports when it has had all of its own. Buffers are the
 * default (65,536 events), more than the {@code events} each object can have queued.
 */
final class FjThroughput implements Workload {
  private final ActiveRuntime runtime;
  private final Failures failures;
  private final int objects;
  private final int events;

  FjThroughput(ActiveRuntime runtime, Failures failures, int objects, int events) {
    this.runtime = runtime;
    this.failures = failures;
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
    List<ActiveObject<Receiver>> receivers = new ArrayList<>(objects);
    for (int i = 0; i < objects; i++) {
      receivers.add(runtime.spawn(new Receiver(events, finished, done)));
    }
    return new Trial() {
      @Override
      public long run() throws InterruptedException {
        for (int e = 0; e < events; e++) {
          for (ActiveObject<Receiver> r : receivers) {
            r.send(Receiver::event);
          }
        }
        // Each receiver counts down once, at exactly its expected count: a lost event hangs the
        // run, and the wait then fails it.
        failures.await(done, "fjthrput");
        return (long) objects * events;
      }

      @Override
      public void close() {
        receivers.forEach(ActiveObject::stop);
      }
    };
  }
}

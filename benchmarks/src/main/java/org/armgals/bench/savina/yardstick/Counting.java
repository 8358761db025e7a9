package org.armgals.bench.savina.yardstick;

import java.util.concurrent.CompletableFuture;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.Trial;
import org.armgals.bench.savina.Workload;

/**
 * The main thread sends {@code increments} increments to one counter, then asks it for the total.
 * The mailbox is unbounded.
 */
final class Counting implements Workload {
  private final YardstickSuite suite;
  private final int increments;

  Counting(YardstickSuite suite, int increments) {
    this.suite = suite;
    this.increments = increments;
  }

  /** The counter. */
  static final class Counter {
    private long count;

    void increment() {
      count++;
    }

    long count() {
      return count;
    }
  }

  @Override
  public Trial prepare() {
    Actor<Counter> counter = suite.spawn(new Counter());
    return new Trial() {
      @Override
      public long run() throws InterruptedException {
        for (int i = 0; i < increments; i++) {
          counter.send(Counter::increment);
        }
        CompletableFuture<Long> total = new CompletableFuture<>();
        counter.send(c -> total.complete(c.count()));
        Check.equal("counting: the counter's total", increments, suite.await(total, "counting"));
        return increments;
      }

      @Override
      public void close() {}
    };
  }
}

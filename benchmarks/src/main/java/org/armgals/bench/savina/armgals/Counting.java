package org.armgals.bench.savina.armgals;

import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.Trial;
import org.armgals.bench.savina.Workload;

/**
 * The main thread sends {@code increments} one-way increments to one counter, then asks it for the
 * total with a synchronized request.
 *
 * <p>The counter has the default buffer: {@code ObjectConfig.DEFAULT_CAPACITY} (65,536) events,
 * blocking the sender when full. The sender outruns the counter, so this workload also measures the
 * runtime's back-pressure (Pekko's default mailbox is unbounded and has none).
 */
final class Counting implements Workload {
  private final ActiveRuntime runtime;
  private final int increments;

  Counting(ActiveRuntime runtime, int increments) {
    this.runtime = runtime;
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
    ActiveObject<Counter> counter = runtime.spawn(new Counter());
    return new Trial() {
      @Override
      public long run() {
        for (int i = 0; i < increments; i++) {
          counter.send(Counter::increment);
        }
        long total = counter.call(Counter::count).getValue(Check.STUCK);
        Check.equal("counting: the counter's total", increments, total);
        return increments;
      }

      @Override
      public void close() {
        counter.stop();
      }
    };
  }
}

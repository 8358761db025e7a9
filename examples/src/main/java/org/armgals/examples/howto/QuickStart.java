package org.armgals.examples.howto;

import java.time.Duration;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.FutureValue;

/**
 * The README's first example: a runtime, an object, a one-way and a synchronized request, a proxy.
 */
public final class QuickStart {
  private QuickStart() {}

  // tag::servant[]
  /** What the proxy offers: void methods become one-way requests, futures synchronized ones. */
  public interface Tally {
    void add(long n);

    FutureValue<Long> total();
  }

  /** The servant: plain code. Its active object runs it on one thread at a time. */
  public static final class Counter implements Tally {
    private long count;

    @Override
    public void add(long n) {
      count += n;
    }

    @Override
    public FutureValue<Long> total() {
      return FutureValue.completed(count);
    }

    public long count() {
      return count;
    }
  }

  // end::servant[]

  // tag::main[]
  public static void main(String[] args) {
    try (ActiveRuntime runtime = ActiveRuntime.create()) {
      ActiveObject<Counter> counter = runtime.spawn(new Counter());

      counter.send(c -> c.add(2)); // a one-way request: returns at once
      FutureValue<Long> count = counter.call(Counter::count); // a synchronized request
      System.out.println("count = " + count.getValue()); // waits by necessity: 2

      Tally tally = counter.proxy(Tally.class); // the same object, behind its interface
      tally.add(40);
      System.out.println("total = " + tally.total().getValue(Duration.ofSeconds(5))); // 42
    }
  }
  // end::main[]
}

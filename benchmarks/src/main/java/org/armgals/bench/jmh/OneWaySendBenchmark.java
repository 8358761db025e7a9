package org.armgals.bench.jmh;

import java.util.concurrent.TimeUnit;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * One-way send and processing throughput: the benchmark thread sends a batch of one-way requests to
 * one object, then waits, with a synchronized request queued behind them, until the object has
 * processed them all. A score is one-way requests sent and processed per second.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class OneWaySendBenchmark {
  static final int BATCH = 10_000;

  /** The servant: a counter. */
  static final class Counter {
    private long count;

    void increment() {
      count++;
    }

    long count() {
      return count;
    }
  }

  private ActiveRuntime runtime;
  private ActiveObject<Counter> counter;
  private long expected;

  /** A fresh runtime and object for each trial. */
  @Setup(Level.Trial)
  public void start() {
    runtime = ActiveRuntime.builder().name("jmh-one-way").jmx(false).build();
    counter = runtime.spawn(new Counter());
    expected = 0;
  }

  /** Shuts the runtime down. */
  @TearDown(Level.Trial)
  public void stop() {
    runtime.close();
  }

  /** Sends {@link #BATCH} increments, then waits for the count that includes them. */
  @Benchmark
  @OperationsPerInvocation(BATCH)
  public long sendAndProcess() {
    for (int i = 0; i < BATCH; i++) {
      counter.send(Counter::increment);
    }
    expected += BATCH;
    long count = counter.call(Counter::count).getValue();
    if (count != expected) {
      throw new IllegalStateException("count: expected " + expected + ", got " + count);
    }
    return count;
  }
}

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
 * The round trip of a synchronized request: {@code call(...)} then {@code getValue()}, from a
 * thread outside the runtime (the benchmark thread) and from inside another active object (where
 * the wait by necessity parks the caller's virtual thread). A score is the average time of one
 * round trip.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class CallRoundTripBenchmark {
  static final int INNER = 1_000;

  /** The server: answers with its argument plus one. */
  static final class Echo {
    long next(long value) {
      return value + 1;
    }
  }

  /** The client object of {@link #fromObject()}: makes {@link #INNER} calls in a row. */
  static final class Client {
    private final ActiveObject<Echo> echo;

    Client(ActiveObject<Echo> echo) {
      this.echo = echo;
    }

    long calls() {
      long sum = 0;
      for (long i = 0; i < INNER; i++) {
        long value = i;
        sum += echo.call(e -> e.next(value)).getValue();
      }
      return sum;
    }
  }

  private ActiveRuntime runtime;
  private ActiveObject<Echo> echo;
  private ActiveObject<Client> client;
  private long next;

  /** A fresh runtime, server and client for each trial. */
  @Setup(Level.Trial)
  public void start() {
    runtime = ActiveRuntime.builder().name("jmh-call").jmx(false).build();
    echo = runtime.spawn(new Echo());
    client = runtime.spawn(new Client(echo));
  }

  /** Shuts the runtime down. */
  @TearDown(Level.Trial)
  public void stop() {
    runtime.close();
  }

  /** One round trip from the benchmark thread. */
  @Benchmark
  public long fromOutside() {
    long value = next++;
    return echo.call(e -> e.next(value)).getValue();
  }

  /** {@link #INNER} round trips from inside the client object, per invocation. */
  @Benchmark
  @OperationsPerInvocation(INNER)
  public long fromObject() {
    return client.call(Client::calls).getValue();
  }
}

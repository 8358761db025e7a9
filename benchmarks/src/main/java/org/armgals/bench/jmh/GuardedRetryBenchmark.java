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
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Guarded events (paper §4.1, {@code isProcessable}): {@code waiting} requests guarded by a closed
 * gate are sent and found not processable (deferred); then one request opens the gate, and each
 * deferred request is retried and runs. A score is the time of one such batch, deferrals and
 * retries included; divide by {@code waiting} for the cost of one guarded request.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class GuardedRetryBenchmark {

  /** A gate: passes are guarded by its being open. */
  static final class Gate {
    private boolean open;
    private int passed;

    boolean isOpen() {
      return open;
    }

    void open() {
      open = true;
    }

    void pass() {
      passed++;
    }

    /** Closes the gate again and says how many passed since the last close. */
    int close() {
      int n = passed;
      passed = 0;
      open = false;
      return n;
    }
  }

  /** How many guarded requests wait at once. */
  @Param({"1", "16", "256"})
  public int waiting;

  private ActiveRuntime runtime;
  private ActiveObject<Gate> gate;

  /** A fresh runtime and gate for each trial. */
  @Setup(Level.Trial)
  public void start() {
    runtime = ActiveRuntime.builder().name("jmh-guard").jmx(false).build();
    gate = runtime.spawn(new Gate());
  }

  /** Shuts the runtime down. */
  @TearDown(Level.Trial)
  public void stop() {
    runtime.close();
  }

  /**
   * Sends {@link #waiting} guarded passes, opens the gate, and waits until all have passed. The
   * passes are queued before the request that opens the gate, so each is deferred once and retried
   * once.
   */
  @Benchmark
  public int deferThenRetry() {
    for (int i = 0; i < waiting; i++) {
      gate.sendWhen(Gate::isOpen, Gate::pass);
    }
    gate.send(Gate::open);
    int passed = gate.call(Gate::close).getValue();
    if (passed != waiting) {
      throw new IllegalStateException("passed: expected " + waiting + ", got " + passed);
    }
    return passed;
  }
}

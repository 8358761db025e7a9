package org.armgals.examples;

import java.io.PrintStream;
import java.time.Duration;
import java.util.concurrent.atomic.AtomicLong;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.RuntimeStats;
import org.armgals.active.ShutdownMode;

/**
 * The armgals demo: active objects in both modes, in one short run. Run it with {@code ./mvnw -q
 * -pl examples -am verify -Pdemo -DskipTests}.
 */
public final class Demo {
  private static final Duration TIMEOUT = Duration.ofSeconds(30);

  private Demo() {}

  /** What one run of the demo observed. */
  public record Outcome(
      GuardedBufferDemo.Result buffer,
      FuturesDemo.Result futures,
      ReactiveDemo.Result reactive,
      long handledFailures,
      boolean cleanShutdown,
      RuntimeStats stats) {}

  public static void main(String[] args) {
    run(System.out);
  }

  /** Runs the three parts on one runtime, prints an account of them on {@code out}. */
  public static Outcome run(PrintStream out) {
    AtomicLong handled = new AtomicLong();
    ActiveRuntime runtime =
        ActiveRuntime.builder()
            .name("demo")
            // Failures are part of the story here; count them instead of logging stack traces.
            .errorHandler((object, event, error) -> handled.incrementAndGet())
            .build();
    out.println("armgals demo: runtime '" + runtime.name() + "'");
    out.println();
    GuardedBufferDemo.Result buffer = GuardedBufferDemo.run(runtime, out, TIMEOUT);
    out.println();
    FuturesDemo.Result futures = FuturesDemo.run(runtime, out, TIMEOUT);
    out.println();
    ReactiveDemo.Result reactive = ReactiveDemo.run(runtime, out, 4);
    out.println();
    RuntimeStats stats = runtime.stats();
    boolean clean = runtime.shutdown(ShutdownMode.DRAIN, TIMEOUT);
    out.println("the error handler heard " + handled.get() + " failures (the gizmo and the cycle)");
    out.println("runtime shut down " + (clean ? "cleanly" : "with leftovers") + "; " + stats);
    return new Outcome(buffer, futures, reactive, handled.get(), clean, stats);
  }
}

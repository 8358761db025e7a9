package org.armgals.bench.savina.armgals;

import java.time.Duration;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.ShutdownMode;
import org.armgals.bench.savina.IdleObjects;
import org.armgals.bench.savina.Savina;
import org.armgals.bench.savina.Sizes;
import org.armgals.bench.savina.Suite;
import org.armgals.bench.savina.Workload;

/**
 * The workloads on one armgals runtime with the default settings (one worker per core), except that
 * a failure in any object fails the run at once instead of being only logged.
 */
public final class ArmgalsSuite implements Suite {
  private final Sizes sizes;
  private final Failures failures = new Failures();
  private final ActiveRuntime runtime;

  /** Starts the runtime. */
  public ArmgalsSuite(Sizes sizes) {
    this.sizes = sizes;
    this.runtime = ActiveRuntime.builder().name("savina").errorHandler(failures).build();
  }

  @Override
  public String impl() {
    return "armgals";
  }

  @Override
  public Workload workload(String name) {
    return switch (name) {
      case "pingpong" -> new PingPong(runtime, failures, sizes.pingpongMessages());
      case "counting" -> new Counting(runtime, sizes.countingIncrements());
      case "threadring" -> new ThreadRing(runtime, failures, sizes.ringObjects(), sizes.ringLaps());
      case "fjthrput" ->
          new FjThroughput(runtime, failures, sizes.fjObjects(), sizes.fjEventsPerObject());
      case "creation" -> new Creation(runtime, failures, sizes.creationObjects());
      case "futurertt" -> new FutureRtt(runtime, sizes.futureRequests());
      default ->
          throw new IllegalArgumentException(
              "unknown workload '" + name + "'; expected one of " + Savina.WORKLOADS);
    };
  }

  @Override
  public IdleObjects idleObjects() {
    return new IdlePopulation(runtime);
  }

  @Override
  public void close() {
    runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(10));
  }
}

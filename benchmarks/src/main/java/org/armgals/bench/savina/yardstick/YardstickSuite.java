package org.armgals.bench.savina.yardstick;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.TimeUnit;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.IdleObjects;
import org.armgals.bench.savina.Savina;
import org.armgals.bench.savina.Sizes;
import org.armgals.bench.savina.Suite;
import org.armgals.bench.savina.Workload;

/**
 * The workloads on one {@link ForkJoinPool} of one thread per core, in asynchronous (FIFO) mode as
 * its documentation advises for event-style tasks; a failure in any actor fails the run at once.
 */
public final class YardstickSuite implements Suite {
  private final Sizes sizes;
  private final CompletableFuture<Void> firstFailure = new CompletableFuture<>();
  private final ForkJoinPool pool;

  /** Starts the pool. */
  public YardstickSuite(Sizes sizes) {
    this.sizes = sizes;
    this.pool =
        new ForkJoinPool(
            Runtime.getRuntime().availableProcessors(),
            ForkJoinPool.defaultForkJoinWorkerThreadFactory,
            (thread, error) ->
                firstFailure.completeExceptionally(
                    new IllegalStateException("an actor failed on " + thread.getName(), error)),
            true);
  }

  @Override
  public String impl() {
    return "yardstick";
  }

  @Override
  public Workload workload(String name) {
    return switch (name) {
      case "pingpong" -> new PingPong(this, sizes.pingpongMessages());
      case "counting" -> new Counting(this, sizes.countingIncrements());
      case "threadring" -> new ThreadRing(this, sizes.ringObjects(), sizes.ringLaps());
      case "fjthrput" -> new FjThroughput(this, sizes.fjObjects(), sizes.fjEventsPerObject());
      case "creation" -> new Creation(this, sizes.creationObjects());
      case "futurertt" -> new FutureRtt(this, sizes.futureRequests());
      default ->
          throw new IllegalArgumentException(
              "unknown workload '" + name + "'; expected one of " + Savina.WORKLOADS);
    };
  }

  @Override
  public IdleObjects idleObjects() {
    return new IdlePopulation(this);
  }

  /** A new actor around {@code state}. */
  <T> Actor<T> spawn(T state) {
    return new Actor<>(pool, state);
  }

  /**
   * The value of {@code done}, waiting as {@link Check#await} does.
   *
   * @throws IllegalStateException an actor failed, or {@code done} did not complete in time
   */
  <T> T await(CompletableFuture<T> done, String what) throws InterruptedException {
    Check.await(CompletableFuture.anyOf(done, firstFailure), what);
    return done.join();
  }

  @Override
  public void close() {
    pool.shutdownNow();
    try {
      pool.awaitTermination(10, TimeUnit.SECONDS);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }
}

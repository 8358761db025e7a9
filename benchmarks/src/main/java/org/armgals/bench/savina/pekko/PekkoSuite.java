package org.armgals.bench.savina.pekko;

import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Function;
import org.apache.pekko.actor.typed.ActorSystem;
import org.apache.pekko.actor.typed.SpawnProtocol;
import org.apache.pekko.actor.typed.javadsl.ActorContext;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.IdleObjects;
import org.armgals.bench.savina.Savina;
import org.armgals.bench.savina.Sizes;
import org.armgals.bench.savina.Suite;
import org.armgals.bench.savina.Workload;

/**
 * The workloads on one Pekko actor system with the default configuration (default dispatcher and
 * mailbox); {@code application.conf} only quiets the log.
 */
public final class PekkoSuite implements Suite {
  private final Sizes sizes;
  private final ActorSystem<SpawnProtocol.Command> system;
  private int roots;

  /** Starts the actor system. */
  public PekkoSuite(Sizes sizes) {
    this.sizes = sizes;
    this.system = ActorSystem.create(SpawnProtocol.create(), "savina");
  }

  @Override
  public String impl() {
    return "pekko";
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

  ActorSystem<SpawnProtocol.Command> system() {
    return system;
  }

  /** A new root for the actors of one run: see {@link TrialRoot#spawn}. */
  <T> TrialRoot<T> root(String workload, Function<ActorContext<TrialRoot.Stop>, T> build)
      throws InterruptedException {
    return TrialRoot.spawn(system, workload + "-" + ++roots, build);
  }

  /** Terminates the actor system; stopping the million actors of the memory probe takes a while. */
  @Override
  public void close() {
    system.terminate();
    try {
      system
          .getWhenTerminated()
          .toCompletableFuture()
          .get(Check.STUCK.toSeconds(), TimeUnit.SECONDS);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } catch (ExecutionException | TimeoutException e) {
      throw new IllegalStateException(
          "the actor system did not terminate within " + Check.STUCK, e);
    }
  }
}

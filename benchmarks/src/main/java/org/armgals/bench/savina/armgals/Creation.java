package org.armgals.bench.savina.armgals;

import java.util.concurrent.CompletableFuture;
import org.armgals.active.ActiveContext;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.ObjectConfig;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.Trial;
import org.armgals.bench.savina.Workload;

/**
 * A creator object creates {@code objects} objects and greets each; each replies once to the
 * creator and stops itself (as a Pekko child returns {@code Behaviors.stopped()}).
 *
 * <p>The creator's buffer holds {@code objects} events (at least the default): it expects exactly
 * that many replies, and most arrive while it is still busy creating, so a smaller buffer would
 * only park the replying objects until it is done.
 */
final class Creation implements Workload {
  private final ActiveRuntime runtime;
  private final Failures failures;
  private final int objects;

  Creation(ActiveRuntime runtime, Failures failures, int objects) {
    this.runtime = runtime;
    this.failures = failures;
    this.objects = objects;
  }

  /** Creates the children and counts their replies. */
  static final class Creator {
    private final ActiveRuntime runtime;
    private final int objects;
    private final CompletableFuture<Integer> done;
    private int replies;

    Creator(ActiveRuntime runtime, int objects, CompletableFuture<Integer> done) {
      this.runtime = runtime;
      this.objects = objects;
      this.done = done;
    }

    void create() {
      ActiveRef<Creator> self = ActiveContext.self();
      for (int i = 0; i < objects; i++) {
        runtime.spawn(new Child()).send(child -> child.greet(self));
      }
    }

    void reply() {
      if (++replies == objects) {
        done.complete(replies);
      }
    }
  }

  /** A created object: replies to its greeting, then stops. */
  static final class Child {
    void greet(ActiveRef<Creator> creator) {
      creator.send(Creator::reply);
      ActiveContext.current().ifPresent(ActiveObject::stop);
    }
  }

  @Override
  public Trial prepare() {
    CompletableFuture<Integer> done = new CompletableFuture<>();
    ObjectConfig config =
        ObjectConfig.asynchronous().withCapacity(Math.max(objects, ObjectConfig.DEFAULT_CAPACITY));
    ActiveObject<Creator> creator = runtime.spawn(new Creator(runtime, objects, done), config);
    return new Trial() {
      @Override
      public long run() throws InterruptedException {
        creator.send(Creator::create);
        int replies = failures.await(done, "creation");
        Check.equal("creation: replies to the creator", objects, replies);
        return objects;
      }

      @Override
      public void close() {
        creator.stop();
      }
    };
  }
}

package org.armgals.bench.savina.yardstick;

import java.util.concurrent.CompletableFuture;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.Trial;
import org.armgals.bench.savina.Workload;

/**
 * A creator actor creates {@code objects} actors and greets each; each replies once to the creator.
 * A hand-written actor has nothing to stop: once it has replied, nothing refers to it and it is
 * garbage.
 */
final class Creation implements Workload {
  private final YardstickSuite suite;
  private final int objects;

  Creation(YardstickSuite suite, int objects) {
    this.suite = suite;
    this.objects = objects;
  }

  /** Creates the children and counts their replies. */
  static final class Creator {
    private final YardstickSuite suite;
    private final int objects;
    private final CompletableFuture<Integer> done;
    private int replies;

    Creator(YardstickSuite suite, int objects, CompletableFuture<Integer> done) {
      this.suite = suite;
      this.objects = objects;
      this.done = done;
    }

    void create(Actor<Creator> self) {
      for (int i = 0; i < objects; i++) {
        suite.spawn(new Child()).send(child -> child.greet(self));
      }
    }

    void reply() {
      if (++replies == objects) {
        done.complete(replies);
      }
    }
  }

  /** A created actor: replies to its greeting. */
  static final class Child {
    void greet(Actor<Creator> creator) {
      creator.send(Creator::reply);
    }
  }

  @Override
  public Trial prepare() {
    CompletableFuture<Integer> done = new CompletableFuture<>();
    Actor<Creator> creator = suite.spawn(new Creator(suite, objects, done));
    return new Trial() {
      @Override
      public long run() throws InterruptedException {
        creator.send(c -> c.create(creator));
        int replies = suite.await(done, "creation");
        Check.equal("creation: replies to the creator", objects, replies);
        return objects;
      }

      @Override
      public void close() {}
    };
  }
}

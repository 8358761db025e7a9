package org.armgals.bench.savina.pekko;

import java.util.concurrent.CompletableFuture;
import org.apache.pekko.actor.typed.ActorRef;
import org.apache.pekko.actor.typed.Behavior;
import org.apache.pekko.actor.typed.javadsl.AbstractBehavior;
import org.apache.pekko.actor.typed.javadsl.ActorContext;
import org.apache.pekko.actor.typed.javadsl.Behaviors;
import org.apache.pekko.actor.typed.javadsl.Receive;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.Trial;
import org.armgals.bench.savina.Workload;

/**
 * A creator actor spawns {@code objects} children and greets each; each replies once to the creator
 * and stops.
 */
final class Creation implements Workload {
  private final PekkoSuite suite;
  private final int objects;

  Creation(PekkoSuite suite, int objects) {
    this.suite = suite;
    this.objects = objects;
  }

  /** What the creator understands. */
  sealed interface Command {}

  /** Start creating. */
  enum Create implements Command {
    INSTANCE
  }

  /** A child's reply. */
  enum Reply implements Command {
    INSTANCE
  }

  /** The greeting a child gets. */
  record Greet(ActorRef<Command> creator) {}

  /** A child: replies to its greeting, then stops. Stateless, so one behavior serves them all. */
  static final Behavior<Greet> CHILD =
      Behaviors.receiveMessage(
          greet -> {
            greet.creator().tell(Reply.INSTANCE);
            return Behaviors.stopped();
          });

  /** Spawns the children and counts their replies. */
  static final class Creator extends AbstractBehavior<Command> {
    private final int objects;
    private final CompletableFuture<Integer> done;
    private int replies;

    Creator(ActorContext<Command> context, int objects, CompletableFuture<Integer> done) {
      super(context);
      this.objects = objects;
      this.done = done;
    }

    @Override
    public Receive<Command> createReceive() {
      return newReceiveBuilder()
          .onMessage(Create.class, this::create)
          .onMessage(Reply.class, this::reply)
          .build();
    }

    private Behavior<Command> create(Create create) {
      ActorRef<Command> self = getContext().getSelf();
      for (int i = 0; i < objects; i++) {
        getContext().spawnAnonymous(CHILD).tell(new Greet(self));
      }
      return this;
    }

    private Behavior<Command> reply(Reply reply) {
      if (++replies == objects) {
        done.complete(replies);
      }
      return this;
    }
  }

  @Override
  public Trial prepare() throws InterruptedException {
    CompletableFuture<Integer> done = new CompletableFuture<>();
    TrialRoot<ActorRef<Command>> root =
        suite.root(
            "creation",
            ctx -> ctx.spawn(Behaviors.setup(c -> new Creator(c, objects, done)), "creator"));
    ActorRef<Command> creator = root.actors();
    return new Trial() {
      @Override
      public long run() throws InterruptedException {
        creator.tell(Create.INSTANCE);
        int replies = Check.await(done, "creation");
        Check.equal("creation: replies to the creator", objects, replies);
        return objects;
      }

      @Override
      public void close() {
        root.close();
      }
    };
  }
}

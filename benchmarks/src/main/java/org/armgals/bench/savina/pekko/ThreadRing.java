package org.armgals.bench.savina.pekko;

import java.util.ArrayList;
import java.util.List;
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
import org.jspecify.annotations.Nullable;

/** A token goes {@code laps} times round a ring of {@code objects} actors, one hop a message. */
final class ThreadRing implements Workload {
  private final PekkoSuite suite;
  private final int objects;
  private final int laps;

  ThreadRing(PekkoSuite suite, int objects, int laps) {
    this.suite = suite;
    this.objects = objects;
    this.laps = laps;
  }

  /** What a member understands. */
  sealed interface Command {}

  /** Who comes next in the ring. */
  record Link(ActorRef<Command> next) implements Command {}

  /** The token, with its hop number. */
  record Token(long hop) implements Command {}

  /** A member of the ring: passes the token on until it has made all its hops. */
  static final class Member extends AbstractBehavior<Command> {
    private final long hops;
    private final CompletableFuture<Long> done;
    private @Nullable ActorRef<Command> next;
    private long received;

    Member(ActorContext<Command> context, long hops, CompletableFuture<Long> done) {
      super(context);
      this.hops = hops;
      this.done = done;
    }

    @Override
    public Receive<Command> createReceive() {
      return newReceiveBuilder()
          .onMessage(Link.class, this::link)
          .onMessage(Token.class, this::token)
          .build();
    }

    private Behavior<Command> link(Link link) {
      next = link.next();
      return this;
    }

    private Behavior<Command> token(Token token) {
      received++;
      ActorRef<Command> n = next;
      if (token.hop() == hops || n == null) {
        done.complete(received);
      } else {
        n.tell(new Token(token.hop() + 1));
      }
      return this;
    }
  }

  @Override
  public Trial prepare() throws InterruptedException {
    long hops = (long) objects * laps;
    CompletableFuture<Long> done = new CompletableFuture<>();
    TrialRoot<List<ActorRef<Command>>> root =
        suite.root(
            "threadring",
            ctx -> {
              Behavior<Command> member = Behaviors.setup(c -> new Member(c, hops, done));
              List<ActorRef<Command>> ring = new ArrayList<>(objects);
              for (int i = 0; i < objects; i++) {
                ring.add(ctx.spawn(member, "member-" + i));
              }
              for (int i = 0; i < objects; i++) {
                ring.get(i).tell(new Link(ring.get((i + 1) % objects)));
              }
              return ring;
            });
    ActorRef<Command> first = root.actors().get(0);
    return new Trial() {
      @Override
      public long run() throws InterruptedException {
        first.tell(new Token(1));
        long received = Check.await(done, "threadring");
        // The last hop lands on the last member, which the token has then visited once per lap.
        Check.equal("threadring: tokens seen by the last member", laps, received);
        return hops;
      }

      @Override
      public void close() {
        root.close();
      }
    };
  }
}

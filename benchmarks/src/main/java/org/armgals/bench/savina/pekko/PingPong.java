package org.armgals.bench.savina.pekko;

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

/** Two actors bounce a ball until it has travelled {@code messages} times. */
final class PingPong implements Workload {
  private final PekkoSuite suite;
  private final int messages;

  PingPong(PekkoSuite suite, int messages) {
    this.suite = suite;
    this.messages = messages;
  }

  /** The ball: its hop number and who hit it. */
  record Ball(long hop, ActorRef<Ball> from) {}

  /** A player: hits the ball back until it has made all its hops. */
  static final class Player extends AbstractBehavior<Ball> {
    private final long hops;
    private final CompletableFuture<Long> done;
    private long received;

    Player(ActorContext<Ball> context, long hops, CompletableFuture<Long> done) {
      super(context);
      this.hops = hops;
      this.done = done;
    }

    @Override
    public Receive<Ball> createReceive() {
      return newReceiveBuilder().onMessage(Ball.class, this::hit).build();
    }

    private Behavior<Ball> hit(Ball ball) {
      received++;
      if (ball.hop() == hops) {
        done.complete(received);
      } else {
        ball.from().tell(new Ball(ball.hop() + 1, getContext().getSelf()));
      }
      return this;
    }
  }

  @Override
  public Trial prepare() throws InterruptedException {
    CompletableFuture<Long> done = new CompletableFuture<>();
    TrialRoot<List<ActorRef<Ball>>> root =
        suite.root(
            "pingpong",
            ctx -> {
              Behavior<Ball> player = Behaviors.setup(c -> new Player(c, messages, done));
              return List.of(ctx.spawn(player, "ping"), ctx.spawn(player, "pong"));
            });
    ActorRef<Ball> ping = root.actors().get(0);
    ActorRef<Ball> pong = root.actors().get(1);
    return new Trial() {
      @Override
      public long run() throws InterruptedException {
        ping.tell(new Ball(1, pong));
        long received = Check.await(done, "pingpong");
        // The ball alternates, so the player that takes the last hop took exactly half of them.
        Check.equal("pingpong: hits taken by the last player", messages / 2, received);
        return messages;
      }

      @Override
      public void close() {
        root.close();
      }
    };
  }
}

package org.armgals.bench.savina.yardstick;

import java.util.concurrent.CompletableFuture;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.Trial;
import org.armgals.bench.savina.Workload;
import org.jspecify.annotations.Nullable;

/** Two actors bounce a ball until it has travelled {@code messages} times. */
final class PingPong implements Workload {
  private final YardstickSuite suite;
  private final int messages;

  PingPong(YardstickSuite suite, int messages) {
    this.suite = suite;
    this.messages = messages;
  }

  /** A player: hits the ball back to its partner until the ball has made all its hops. */
  static final class Player {
    private final long hops;
    private final CompletableFuture<Long> done;
    private @Nullable Actor<Player> partner;
    private long received;

    Player(long hops, CompletableFuture<Long> done) {
      this.hops = hops;
      this.done = done;
    }

    void meet(Actor<Player> partner) {
      this.partner = partner;
    }

    void hit(long hop) {
      received++;
      Actor<Player> p = partner;
      if (hop == hops || p == null) {
        done.complete(received);
      } else {
        p.send(player -> player.hit(hop + 1));
      }
    }
  }

  @Override
  public Trial prepare() {
    CompletableFuture<Long> done = new CompletableFuture<>();
    Actor<Player> ping = suite.spawn(new Player(messages, done));
    Actor<Player> pong = suite.spawn(new Player(messages, done));
    ping.send(p -> p.meet(pong));
    pong.send(p -> p.meet(ping));
    return new Trial() {
      @Override
      public long run() throws InterruptedException {
        ping.send(p -> p.hit(1));
        long received = suite.await(done, "pingpong");
        // The ball alternates, so the player that takes the last hop took exactly half of them.
        Check.equal("pingpong: hits taken by the last player", messages / 2, received);
        return messages;
      }

      @Override
      public void close() {}
    };
  }
}

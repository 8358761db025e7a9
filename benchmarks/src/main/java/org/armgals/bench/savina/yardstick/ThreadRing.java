package org.armgals.bench.savina.yardstick;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.Trial;
import org.armgals.bench.savina.Workload;
import org.jspecify.annotations.Nullable;

/** A token goes {@code laps} times round a ring of {@code objects} actors, one hop a message. */
final class ThreadRing implements Workload {
  private final YardstickSuite suite;
  private final int objects;
  private final int laps;

  ThreadRing(YardstickSuite suite, int objects, int laps) {
    this.suite = suite;
    this.objects = objects;
    this.laps = laps;
  }

  /** A member of the ring: passes the token on until it has made all its hops. */
  static final class Member {
    private final long hops;
    private final CompletableFuture<Long> done;
    private @Nullable Actor<Member> next;
    private long received;

    Member(long hops, CompletableFuture<Long> done) {
      this.hops = hops;
      this.done = done;
    }

    void link(Actor<Member> next) {
      this.next = next;
    }

    void token(long hop) {
      received++;
      Actor<Member> n = next;
      if (hop == hops || n == null) {
        done.complete(received);
      } else {
        n.send(member -> member.token(hop + 1));
      }
    }
  }

  @Override
  public Trial prepare() {
    long hops = (long) objects * laps;
    CompletableFuture<Long> done = new CompletableFuture<>();
    List<Actor<Member>> ring = new ArrayList<>(objects);
    for (int i = 0; i < objects; i++) {
      ring.add(suite.spawn(new Member(hops, done)));
    }
    for (int i = 0; i < objects; i++) {
      Actor<Member> next = ring.get((i + 1) % objects);
      ring.get(i).send(m -> m.link(next));
    }
    return new Trial() {
      @Override
      public long run() throws InterruptedException {
        ring.get(0).send(m -> m.token(1));
        long received = suite.await(done, "threadring");
        // The last hop lands on the last member, which the token has then visited once per lap.
        Check.equal("threadring: tokens seen by the last member", laps, received);
        return hops;
      }

      @Override
      public void close() {}
    };
  }
}

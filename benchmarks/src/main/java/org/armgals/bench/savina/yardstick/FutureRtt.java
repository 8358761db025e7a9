package org.armgals.bench.savina.yardstick;

import java.util.concurrent.CompletableFuture;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.Trial;
import org.armgals.bench.savina.Workload;

/**
 * The main thread makes {@code requests} requests to one actor, one after the other: each carries a
 * {@code CompletableFuture} that the actor completes, awaited before the next is sent.
 */
final class FutureRtt implements Workload {
  private final YardstickSuite suite;
  private final int requests;

  FutureRtt(YardstickSuite suite, int requests) {
    this.suite = suite;
    this.requests = requests;
  }

  /** Answers each request with its argument plus one. */
  static final class Echo {
    long next(long value) {
      return value + 1;
    }
  }

  @Override
  public Trial prepare() {
    Actor<Echo> echo = suite.spawn(new Echo());
    return new Trial() {
      @Override
      public long run() throws InterruptedException {
        for (long i = 0; i < requests; i++) {
          long value = i;
          CompletableFuture<Long> answer = new CompletableFuture<>();
          echo.send(e -> answer.complete(e.next(value)));
          long got = Check.await(answer, "futurertt");
          if (got != i + 1) {
            Check.equal("futurertt: answer to request " + i, i + 1, got);
          }
        }
        return requests;
      }

      @Override
      public void close() {}
    };
  }
}

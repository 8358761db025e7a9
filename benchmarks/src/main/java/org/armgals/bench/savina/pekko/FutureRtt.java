package org.armgals.bench.savina.pekko;

import org.apache.pekko.actor.typed.ActorRef;
import org.apache.pekko.actor.typed.Behavior;
import org.apache.pekko.actor.typed.Scheduler;
import org.apache.pekko.actor.typed.javadsl.AskPattern;
import org.apache.pekko.actor.typed.javadsl.Behaviors;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.Trial;
import org.armgals.bench.savina.Workload;

/**
 * The main thread asks one actor {@code requests} times with {@code AskPattern}, one after the
 * other, each answer awaited before the next ask.
 */
final class FutureRtt implements Workload {
  private final PekkoSuite suite;
  private final int requests;

  FutureRtt(PekkoSuite suite, int requests) {
    this.suite = suite;
    this.requests = requests;
  }

  /** A request: answer {@code value} plus one. */
  record Next(long value, ActorRef<Long> replyTo) {}

  static final Behavior<Next> ECHO =
      Behaviors.receiveMessage(
          next -> {
            next.replyTo().tell(next.value() + 1);
            return Behaviors.same();
          });

  @Override
  public Trial prepare() throws InterruptedException {
    TrialRoot<ActorRef<Next>> root = suite.root("futurertt", ctx -> ctx.spawn(ECHO, "echo"));
    ActorRef<Next> echo = root.actors();
    Scheduler scheduler = suite.system().scheduler();
    return new Trial() {
      @Override
      public long run() throws InterruptedException {
        for (long i = 0; i < requests; i++) {
          long value = i;
          long answer =
              Check.await(
                  AskPattern.<Next, Long>ask(
                          echo, replyTo -> new Next(value, replyTo), Check.STUCK, scheduler)
                      .toCompletableFuture(),
                  "futurertt");
          if (answer != i + 1) {
            Check.equal("futurertt: answer to request " + i, i + 1, answer);
          }
        }
        return requests;
      }

      @Override
      public void close() {
        root.close();
      }
    };
  }
}

package org.armgals.bench.savina.pekko;

import org.apache.pekko.actor.typed.ActorRef;
import org.apache.pekko.actor.typed.Behavior;
import org.apache.pekko.actor.typed.javadsl.AbstractBehavior;
import org.apache.pekko.actor.typed.javadsl.ActorContext;
import org.apache.pekko.actor.typed.javadsl.AskPattern;
import org.apache.pekko.actor.typed.javadsl.Behaviors;
import org.apache.pekko.actor.typed.javadsl.Receive;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.Trial;
import org.armgals.bench.savina.Workload;

/**
 * The main thread tells one counter {@code increments} increments, then asks it for the total. The
 * counter has the default (unbounded) mailbox.
 */
final class Counting implements Workload {
  private final PekkoSuite suite;
  private final int increments;

  Counting(PekkoSuite suite, int increments) {
    this.suite = suite;
    this.increments = increments;
  }

  /** What the counter understands. */
  sealed interface Command {}

  /** Adds one. */
  enum Increment implements Command {
    INSTANCE
  }

  /** Asks for the total. */
  record Total(ActorRef<Long> replyTo) implements Command {}

  /** The counter. */
  static final class Counter extends AbstractBehavior<Command> {
    private long count;

    Counter(ActorContext<Command> context) {
      super(context);
    }

    @Override
    public Receive<Command> createReceive() {
      return newReceiveBuilder()
          .onMessage(Increment.class, this::increment)
          .onMessage(Total.class, this::total)
          .build();
    }

    private Behavior<Command> increment(Increment increment) {
      count++;
      return this;
    }

    private Behavior<Command> total(Total total) {
      total.replyTo().tell(count);
      return this;
    }
  }

  @Override
  public Trial prepare() throws InterruptedException {
    TrialRoot<ActorRef<Command>> root =
        suite.root("counting", ctx -> ctx.spawn(Behaviors.setup(Counter::new), "counter"));
    ActorRef<Command> counter = root.actors();
    return new Trial() {
      @Override
      public long run() throws InterruptedException {
        for (int i = 0; i < increments; i++) {
          counter.tell(Increment.INSTANCE);
        }
        long total =
            Check.await(
                AskPattern.<Command, Long>ask(
                        counter, Total::new, Check.STUCK, suite.system().scheduler())
                    .toCompletableFuture(),
                "counting");
        Check.equal("counting: the counter's total", increments, total);
        return increments;
      }

      @Override
      public void close() {
        root.close();
      }
    };
  }
}

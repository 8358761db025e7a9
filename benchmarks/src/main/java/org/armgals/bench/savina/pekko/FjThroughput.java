package org.armgals.bench.savina.pekko;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicInteger;
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
 * The main thread tells each of {@code objects} actors {@code events} events, round robin; each
 * counts them and reports when it has had all of its own.
 */
final class FjThroughput implements Workload {
  private final PekkoSuite suite;
  private final int objects;
  private final int events;

  FjThroughput(PekkoSuite suite, int objects, int events) {
    this.suite = suite;
    this.objects = objects;
    this.events = events;
  }

  /** The event. */
  enum Event {
    INSTANCE
  }

  /** A receiver: counts its events and, at the last one it expects, tells the run. */
  static final class Receiver extends AbstractBehavior<Event> {
    private final int expected;
    private final AtomicInteger finished;
    private final CompletableFuture<Integer> done;
    private int received;

    Receiver(
        ActorContext<Event> context,
        int expected,
        AtomicInteger finished,
        CompletableFuture<Integer> done) {
      super(context);
      this.expected = expected;
      this.finished = finished;
      this.done = done;
    }

    @Override
    public Receive<Event> createReceive() {
      return newReceiveBuilder().onMessage(Event.class, this::event).build();
    }

    private Behavior<Event> event(Event event) {
      if (++received == expected) {
        int n = finished.decrementAndGet();
        if (n == 0) {
          done.complete(expected);
        }
      }
      return this;
    }
  }

  @Override
  public Trial prepare() throws InterruptedException {
    AtomicInteger finished = new AtomicInteger(objects);
    CompletableFuture<Integer> done = new CompletableFuture<>();
    TrialRoot<List<ActorRef<Event>>> root =
        suite.root(
            "fjthrput",
            ctx -> {
              Behavior<Event> receiver =
                  Behaviors.setup(c -> new Receiver(c, events, finished, done));
              List<ActorRef<Event>> receivers = new ArrayList<>(objects);
              for (int i = 0; i < objects; i++) {
                receivers.add(ctx.spawn(receiver, "receiver-" + i));
              }
              return receivers;
            });
    List<ActorRef<Event>> receivers = root.actors();
    return new Trial() {
      @Override
      public long run() throws InterruptedException {
        for (int e = 0; e < events; e++) {
          for (ActorRef<Event> r : receivers) {
            r.tell(Event.INSTANCE);
          }
        }
        // Each receiver counts down once, at exactly its expected count: a lost event hangs the
        // run, and the wait then fails it.
        Check.await(done, "fjthrput");
        return (long) objects * events;
      }

      @Override
      public void close() {
        root.close();
      }
    };
  }
}

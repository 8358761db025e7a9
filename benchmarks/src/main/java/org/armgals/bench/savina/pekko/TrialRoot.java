package org.armgals.bench.savina.pekko;

import java.util.concurrent.CompletableFuture;
import java.util.function.Function;
import org.apache.pekko.actor.typed.ActorRef;
import org.apache.pekko.actor.typed.ActorSystem;
import org.apache.pekko.actor.typed.Behavior;
import org.apache.pekko.actor.typed.Props;
import org.apache.pekko.actor.typed.SpawnProtocol;
import org.apache.pekko.actor.typed.javadsl.ActorContext;
import org.apache.pekko.actor.typed.javadsl.AskPattern;
import org.apache.pekko.actor.typed.javadsl.Behaviors;
import org.armgals.bench.savina.Check;

/**
 * The actors of one run: children of a root actor spawned through the system's {@link
 * SpawnProtocol}, so that stopping the root stops them all.
 *
 * @param <T> what the root's setup built and hands to the run (references to its children)
 */
final class TrialRoot<T> implements AutoCloseable {

  /** The root's only message. */
  enum Stop {
    INSTANCE
  }

  private final ActorRef<Stop> root;
  private final T actors;

  private TrialRoot(ActorRef<Stop> root, T actors) {
    this.root = root;
    this.actors = actors;
  }

  /**
   * Spawns a root named {@code name} whose setup runs {@code build} (on the root's thread, with the
   * root's context, so the actors it spawns are its children) and waits for what it built.
   */
  static <T> TrialRoot<T> spawn(
      ActorSystem<SpawnProtocol.Command> system, String name, Function<ActorContext<Stop>, T> build)
      throws InterruptedException {
    CompletableFuture<T> built = new CompletableFuture<>();
    Behavior<Stop> behavior =
        Behaviors.setup(
            ctx -> {
              try {
                built.complete(build.apply(ctx));
              } catch (RuntimeException e) {
                built.completeExceptionally(e);
                throw e;
              }
              return Behaviors.receiveMessage(stop -> Behaviors.stopped());
            });
    CompletableFuture<ActorRef<Stop>> spawned =
        AskPattern.<SpawnProtocol.Command, ActorRef<Stop>>ask(
                system,
                replyTo -> new SpawnProtocol.Spawn<>(behavior, name, Props.empty(), replyTo),
                Check.STUCK,
                system.scheduler())
            .toCompletableFuture();
    ActorRef<Stop> root = Check.await(spawned, "spawning " + name);
    return new TrialRoot<>(root, Check.await(built, "setting up " + name));
  }

  /** What the root's setup built. */
  T actors() {
    return actors;
  }

  /** Stops the root and, with it, every actor of the run. */
  @Override
  public void close() {
    root.tell(Stop.INSTANCE);
  }
}

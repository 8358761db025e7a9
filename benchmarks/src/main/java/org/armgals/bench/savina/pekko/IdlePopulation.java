package org.armgals.bench.savina.pekko;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.apache.pekko.actor.typed.ActorRef;
import org.apache.pekko.actor.typed.Behavior;
import org.apache.pekko.actor.typed.javadsl.Behaviors;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.Idle;
import org.armgals.bench.savina.IdleObjects;

/**
 * Idle actors as a Pekko user makes them: children of one parent, each a functional behavior that
 * holds its servant, then one message each. The behavior objects are charged to Pekko: armgals
 * needs nothing around a servant.
 */
final class IdlePopulation implements IdleObjects {
  private final PekkoSuite suite;

  IdlePopulation(PekkoSuite suite) {
    this.suite = suite;
  }

  /** The one message: touch the servant, then count down. */
  record Touch(CountDownLatch touched) {}

  static Behavior<Touch> idle(Idle servant) {
    return Behaviors.receiveMessage(
        touch -> {
          servant.touch();
          touch.touched().countDown();
          return Behaviors.same();
        });
  }

  @Override
  public void populate(Idle[] servants, Object[] handles) throws InterruptedException {
    CountDownLatch touched = new CountDownLatch(servants.length);
    // The root stays alive with its children until the JVM ends: they are what is measured.
    suite.root(
        "mem",
        ctx -> {
          Touch touch = new Touch(touched);
          for (int i = 0; i < servants.length; i++) {
            ActorRef<Touch> actor = ctx.spawnAnonymous(idle(servants[i]));
            actor.tell(touch);
            handles[i] = actor;
          }
          return servants.length;
        });
    Check.state(
        touched.await(Check.STUCK.toSeconds(), TimeUnit.SECONDS),
        "mem: the idle actors did not all process their message within " + Check.STUCK);
  }
}

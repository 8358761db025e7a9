package org.armgals.bench.savina.yardstick;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.Idle;
import org.armgals.bench.savina.IdleObjects;

/** Idle actors: one {@link Actor} around each servant, then one message each. */
final class IdlePopulation implements IdleObjects {
  private final YardstickSuite suite;

  IdlePopulation(YardstickSuite suite) {
    this.suite = suite;
  }

  @Override
  public void populate(Idle[] servants, Object[] handles) throws InterruptedException {
    CountDownLatch touched = new CountDownLatch(servants.length);
    for (int i = 0; i < servants.length; i++) {
      Actor<Idle> actor = suite.spawn(servants[i]);
      actor.send(
          idle -> {
            idle.touch();
            touched.countDown();
          });
      handles[i] = actor;
    }
    Check.state(
        touched.await(Check.STUCK.toSeconds(), TimeUnit.SECONDS),
        "mem: the idle actors did not all process their message within " + Check.STUCK);
  }
}

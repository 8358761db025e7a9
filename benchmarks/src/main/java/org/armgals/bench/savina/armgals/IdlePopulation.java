package org.armgals.bench.savina.armgals;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.Idle;
import org.armgals.bench.savina.IdleObjects;

/**
 * Idle objects as a user makes them: {@code runtime.spawn(servant)} with the default configuration,
 * then one one-way message each.
 */
final class IdlePopulation implements IdleObjects {
  private final ActiveRuntime runtime;

  IdlePopulation(ActiveRuntime runtime) {
    this.runtime = runtime;
  }

  @Override
  public void populate(Idle[] servants, Object[] handles) throws InterruptedException {
    CountDownLatch touched = new CountDownLatch(servants.length);
    for (int i = 0; i < servants.length; i++) {
      ActiveObject<Idle> object = runtime.spawn(servants[i]);
      object.send(
          idle -> {
            idle.touch();
            touched.countDown();
          });
      handles[i] = object;
    }
    Check.state(
        touched.await(Check.STUCK.toSeconds(), TimeUnit.SECONDS),
        "mem: the idle objects did not all process their message within " + Check.STUCK);
  }
}

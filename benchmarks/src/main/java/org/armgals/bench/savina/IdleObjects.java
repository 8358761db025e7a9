package org.armgals.bench.savina;

/** How one implementation makes many idle objects, for {@link HeapProbe#bytesPerIdleObject}. */
@FunctionalInterface
public interface IdleObjects {

  /**
   * Makes one live object around each servant, sends each one message that {@linkplain Idle#touch()
   * touches} its servant, waits until all have processed it, and stores in {@code handles[i]} what
   * keeps object {@code i} reachable (its reference). {@code handles} is as long as {@code
   * servants} and already allocated, so that its own size is not charged to the runtime.
   */
  void populate(Idle[] servants, Object[] handles) throws Exception;
}

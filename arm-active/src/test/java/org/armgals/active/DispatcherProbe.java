package org.armgals.active;

import java.lang.reflect.Field;
import java.time.Duration;
import java.util.Set;
import java.util.concurrent.ConcurrentLinkedQueue;

/**
 * Reaches into a {@link Dispatcher} for the stress tests: its run queue, to run activations by hand
 * ({@link HandDrivenRuntime}), and its set of live workers, to check that a shut-down runtime
 * leaves no thread behind. The dispatcher has no invoker that steps it by hand (STYLE rule 4), so
 * this reads its private fields by name; a rename there fails these tests loudly, at once.
 */
final class DispatcherProbe {
  private DispatcherProbe() {}

  /** The dispatcher's queue of objects that hold their SCHEDULED flag and wait for a worker. */
  @SuppressWarnings("unchecked")
  static ConcurrentLinkedQueue<Core<?>> runQueue(Dispatcher dispatcher) {
    return (ConcurrentLinkedQueue<Core<?>>) field(dispatcher, "runQueue");
  }

  /** How many worker threads are still inside their loop. */
  static int liveWorkers(Dispatcher dispatcher) {
    return ((Set<?>) field(dispatcher, "workers")).size();
  }

  /**
   * Waits until every worker thread of {@code dispatcher} has left its loop.
   *
   * @throws AssertionError some worker is still alive after {@code timeout}
   */
  static void awaitNoLiveWorkers(Dispatcher dispatcher, Duration timeout) {
    long deadline = System.nanoTime() + timeout.toNanos();
    while (liveWorkers(dispatcher) > 0) {
      if (System.nanoTime() - deadline > 0) {
        throw new AssertionError(
            liveWorkers(dispatcher) + " worker thread(s) still alive " + timeout + " after stop");
      }
      Thread.onSpinWait();
    }
  }

  private static Object field(Dispatcher dispatcher, String name) {
    try {
      Field f = Dispatcher.class.getDeclaredField(name);
      f.setAccessible(true);
      return f.get(dispatcher);
    } catch (ReflectiveOperationException e) {
      throw new AssertionError("Dispatcher." + name + " is gone; update DispatcherProbe", e);
    }
  }
}

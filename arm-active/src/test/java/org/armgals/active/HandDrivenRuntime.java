package org.armgals.active;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;

/**
 * A runtime with no worker thread at all: whoever calls {@link #runOne()} does what a worker does,
 * takes the next scheduled object from the run queue and runs one activation of it. Lincheck's
 * model checker controls only its own threads, so every activation must run on one of them;
 * everything else (buffer, SCHEDULED flag, idle re-check, overflow policies) is the real code.
 *
 * <p>Cheap enough to make one per scenario: no thread, no MBean. Failures inside an object are
 * collected by {@link #failures()} instead of being logged.
 */
final class HandDrivenRuntime {
  private final ConcurrentLinkedQueue<Throwable> failures = new ConcurrentLinkedQueue<>();
  private final RuntimeImpl runtime =
      new RuntimeImpl(
          "hand-driven",
          0,
          (object, event, error) -> failures.add(error),
          null,
          TimeSource.system(),
          false);

  /** A new asynchronous object around {@code servant}; it runs only when someone runs it. */
  <S> Core<S> spawn(S servant, ObjectConfig config) {
    return (Core<S>) runtime.spawn(servant, config);
  }

  /** One worker step: runs one activation of the next scheduled object; false if none. */
  boolean runOne() {
    return runtime.dispatcher().runOne();
  }

  /** Runs activations until no object is scheduled. */
  void drain() {
    while (runOne()) {
      // each activation may schedule its object again
    }
  }

  RuntimeStats stats() {
    return runtime.stats();
  }

  /** What the objects' error handler received. */
  List<Throwable> failures() {
    return new ArrayList<>(failures);
  }
}

package org.armgals.active;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;

/**
 * A real runtime for a stress test, with its worker virtual threads, that collects the failures of
 * its objects and, when closed, checks that it shut down cleanly and left no worker alive.
 */
final class LiveRuntime implements AutoCloseable {
  private final ConcurrentLinkedQueue<Throwable> failures = new ConcurrentLinkedQueue<>();
  private final RuntimeImpl runtime;

  LiveRuntime(String name) {
    runtime =
        (RuntimeImpl)
            ActiveRuntime.builder()
                .name(name)
                .jmx(false)
                .errorHandler((object, event, error) -> failures.add(error))
                .build();
  }

  ActiveRuntime runtime() {
    return runtime;
  }

  <S> ActiveObject<S> spawn(S servant, ObjectConfig config) {
    return runtime.spawn(servant, config);
  }

  /** What the objects' error handler received. */
  List<Throwable> failures() {
    return new ArrayList<>(failures);
  }

  /**
   * Shuts the runtime down and waits for its workers to end.
   *
   * @throws AssertionError the shutdown was not clean or a worker is still alive after it
   */
  @Override
  public void close() {
    boolean clean = runtime.shutdown(ShutdownMode.DRAIN, Duration.ofSeconds(10));
    // shutdown joins the workers: none may be left
    int alive = runtime.dispatcher().liveWorkers();
    if (alive > 0) {
      throw new AssertionError(alive + " worker thread(s) still alive after shutdown");
    }
    if (!clean) {
      throw new AssertionError("runtime " + runtime.name() + " did not drain within 10 s");
    }
  }
}

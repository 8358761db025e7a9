package org.armgals.bench.savina.armgals;

import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.bench.savina.Check;
import org.armgals.bench.savina.Trial;
import org.armgals.bench.savina.Workload;

/**
 * The main thread makes {@code requests} synchronized requests to one object, one after the other,
 * each awaited with {@code getValue()} before the next is sent.
 */
final class FutureRtt implements Workload {
  private final ActiveRuntime runtime;
  private final int requests;

  FutureRtt(ActiveRuntime runtime, int requests) {
    this.runtime = runtime;
    this.requests = requests;
  }

  /** Answers each request with its argument plus one. */
  static final class Echo {
    long next(long value) {
      return value + 1;
    }
  }

  @Override
  public Trial prepare() {
    ActiveObject<Echo> echo = runtime.spawn(new Echo());
    return new Trial() {
      @Override
      public long run() {
        for (long i = 0; i < requests; i++) {
          long value = i;
          long answer = echo.call(e -> e.next(value)).getValue(Check.STUCK);
          if (answer != i + 1) {
            Check.equal("futurertt: answer to request " + i, i + 1, answer);
          }
        }
        return requests;
      }

      @Override
      public void close() {
        echo.stop();
      }
    };
  }
}

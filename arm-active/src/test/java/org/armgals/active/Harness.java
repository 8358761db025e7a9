package org.armgals.active;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BooleanSupplier;
import org.jspecify.annotations.Nullable;

/**
 * Runs one contract test in either mode: an asynchronous object runs by itself, a synchronous one
 * is driven by a manual clock that the harness steps until what the test waits for has happened.
 */
final class Harness implements AutoCloseable {
  static final Duration WAIT = Duration.ofSeconds(10);
  static final long MAX_INSTANTS = 1_000;

  final Mode mode;
  final ActiveRuntime runtime;
  final ManualClock clock = Clock.manual(Duration.ofMillis(1));
  final List<Throwable> errors = new CopyOnWriteArrayList<>();

  Harness(Mode mode) {
    this(mode, 2);
  }

  Harness(Mode mode, int workers) {
    this.mode = mode;
    this.runtime =
        ActiveRuntime.builder()
            .workers(workers)
            .jmx(false)
            .errorHandler((object, event, error) -> errors.add(error))
            .build();
  }

  ObjectConfig config() {
    return mode == Mode.ASYNCHRONOUS
        ? ObjectConfig.asynchronous()
        : ObjectConfig.synchronous(clock).withOverflow(OverflowPolicy.reject());
  }

  <S> ActiveObject<S> spawn(S servant) {
    return runtime.spawn(servant, config());
  }

  /** The future's value, stepping the clock in synchronous mode until it is there. */
  <T extends @Nullable Object> T get(FutureValue<T> future) {
    if (mode == Mode.SYNCHRONOUS) {
      clock.stepUntil(future::isDone, MAX_INSTANTS);
    }
    return future.getValue(WAIT);
  }

  /** Waits until {@code condition} holds: steps the clock, or asks the object to report. */
  void awaitUntil(ActiveRef<?> object, BooleanSupplier condition) {
    if (mode == Mode.SYNCHRONOUS) {
      if (!clock.stepUntil(condition, MAX_INSTANTS)) {
        throw new AssertionError("condition not met after " + MAX_INSTANTS + " instants");
      }
      return;
    }
    // Every request queued before this one from this thread has been processed once it answers,
    // and the guard retries until the condition holds.
    object.callWhen(s -> condition.getAsBoolean(), s -> true).getValue(WAIT);
  }

  List<Throwable> errors() {
    return new ArrayList<>(errors);
  }

  @Override
  public void close() {
    runtime.shutdown(ShutdownMode.CANCEL, WAIT);
    clock.close();
  }
}

package org.armgals.gals;

import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import org.armgals.active.TimeSource;

/**
 * How a real-time runner waits for a release. Tests inject one that moves a fake time source
 * instead of waiting, so that overrun policies are tested without sleeping.
 */
@FunctionalInterface
interface Pacing {

  /** Park until this long before a release, then spin: parking alone is too coarse at 1 kHz. */
  long SPIN_NANOS = 100_000;

  /** Parks, then spins until {@code time} reaches {@code due}. */
  Pacing REAL =
      (time, due, stop) -> {
        for (; ; ) {
          long remaining = due - time.nanoTime();
          if (remaining <= 0 || stop.getAsBoolean()) {
            return;
          }
          if (remaining > SPIN_NANOS) {
            LockSupport.parkNanos(remaining - SPIN_NANOS);
          } else {
            Thread.onSpinWait();
          }
        }
      };

  /** Returns once {@code time} has reached {@code due}, or early when {@code stop} holds. */
  void waitUntil(TimeSource time, long due, BooleanSupplier stop);
}

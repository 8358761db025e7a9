package org.armgals.active;

/**
 * A periodic clock on real time. Release {@code k} is due at {@code start + k * period}
 * (drift-free: lateness does not accumulate); the clock thread parks until shortly before that time
 * and spins the rest of the way. An instant that is still running when the next release is due is
 * an <em>overrun</em>: it is counted and the releases that were missed are skipped. Its {@link
 * #stats()} give the actual period, the jitter and the overruns.
 *
 * <p>The clock runs on one platform thread of its own (a release must not wait for a carrier).
 */
public sealed interface RealTimeClock extends Clock permits RealTimeClockImpl {

  /**
   * Starts releasing. Idempotent.
   *
   * @throws IllegalStateException the clock was closed
   */
  void start();
}

package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import org.armgals.active.TimeSource;

/**
 * How a kernel is bootstrapped.
 *
 * @param timeSource where models read time (staleness, damping, resync retries)
 * @param resyncRetry how long a model out of sync waits before asking again, on the next
 *     notification it receives
 * @param jmx whether to register an MBean per entity and per behavioral meta
 */
public record KernelOptions(TimeSource timeSource, Duration resyncRetry, boolean jmx) {

  /** Checks the components. */
  public KernelOptions {
    requireNonNull(timeSource, "timeSource");
    requireNonNull(resyncRetry, "resyncRetry");
    if (resyncRetry.isNegative()) {
      throw new IllegalArgumentException("resyncRetry must be >= 0, was " + resyncRetry);
    }
  }

  /** The system time source, a retry every 100 ms, MBeans registered. */
  public static KernelOptions defaults() {
    return new KernelOptions(TimeSource.system(), Duration.ofMillis(100), true);
  }

  /** These options with another time source. */
  public KernelOptions withTimeSource(TimeSource source) {
    return new KernelOptions(source, resyncRetry, jmx);
  }

  /** These options with MBeans registered or not. */
  public KernelOptions withJmx(boolean register) {
    return new KernelOptions(timeSource, resyncRetry, register);
  }
}

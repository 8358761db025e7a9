package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import org.armgals.active.TimeSource;
import org.armgals.kernel.spi.ReflectionListener;

/**
 * How a kernel is bootstrapped.
 *
 * @param timeSource where models read time (staleness, damping, resync retries), and the time a
 *     base entity stamps on its notifications
 * @param resyncRetry how long a model out of sync waits before asking again, on the next
 *     notification it receives
 * @param jmx whether to register an MBean per entity and per behavioral meta
 * @param listener what hears the reflective loop ({@link ReflectionEvent}); {@link
 *     ReflectionListener#NONE} by default
 * @param stopwatch what times the application of adaptation requests against a reactive entity's
 *     period (the cycle's time budget): real time even when {@code timeSource} is virtual; the
 *     system's monotonic clock by default
 */
public record KernelOptions(
    TimeSource timeSource,
    Duration resyncRetry,
    boolean jmx,
    ReflectionListener listener,
    TimeSource stopwatch) {
  /** Checks the components. */
  public KernelOptions {
    requireNonNull(timeSource, "timeSource");
    requireNonNull(resyncRetry, "resyncRetry");
    requireNonNull(listener, "listener");
    requireNonNull(stopwatch, "stopwatch");
    if (resyncRetry.isNegative()) {
      throw new IllegalArgumentException("resyncRetry must be >= 0, was " + resyncRetry);
    }
  }

  /** Options with this time source, retry and MBeans, no listener and the system's stopwatch. */
  public KernelOptions(TimeSource timeSource, Duration resyncRetry, boolean jmx) {
    this(timeSource, resyncRetry, jmx, ReflectionListener.NONE, TimeSource.system());
  }

  /** The system time source, a retry every 100 ms, MBeans registered. */
  public static KernelOptions defaults() {
    return new KernelOptions(TimeSource.system(), Duration.ofMillis(100), true);
  }

  /** These options with another time source. */
  public KernelOptions withTimeSource(TimeSource source) {
    return new KernelOptions(source, resyncRetry, jmx, listener, stopwatch);
  }

  /** These options with MBeans registered or not. */
  public KernelOptions withJmx(boolean register) {
    return new KernelOptions(timeSource, resyncRetry, register, listener, stopwatch);
  }

  /** These options with {@code reflectionListener} hearing the reflective loop. */
  public KernelOptions withListener(ReflectionListener reflectionListener) {
    return new KernelOptions(timeSource, resyncRetry, jmx, reflectionListener, stopwatch);
  }

  /** These options with another stopwatch for the adaptations' time budget. */
  public KernelOptions withStopwatch(TimeSource adaptationStopwatch) {
    return new KernelOptions(timeSource, resyncRetry, jmx, listener, adaptationStopwatch);
  }
}

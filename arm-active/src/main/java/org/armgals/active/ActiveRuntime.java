package org.armgals.active;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import org.armgals.active.spi.ErrorHandler;
import org.armgals.active.spi.Transport;
import org.jspecify.annotations.Nullable;

/**
 * The facade of the active-object runtime: it creates objects, schedules them on virtual threads,
 * counts what happens, publishes its figures over JMX and shuts down in order.
 *
 * <p>Objects of one runtime talk in memory; events to addresses of other runtimes go through the
 * runtime's {@link Transport}. Asynchronous objects run on a small set of worker virtual threads
 * (one per core by default); an object has a worker only while it has processable events, and a
 * worker that waits by necessity parks without holding a platform thread while another worker takes
 * over.
 *
 * <p>Threading: every method may be called from any thread.
 */
public interface ActiveRuntime extends AutoCloseable {

  /** A runtime with the default settings: see {@link Builder}. */
  static ActiveRuntime create() {
    return builder().build();
  }

  /** A builder of runtimes. */
  static Builder builder() {
    return new Builder();
  }

  /** The runtime's name, the first part of its objects' addresses. */
  String name();

  /** Creates an asynchronous object with the default configuration around {@code servant}. */
  <S> ActiveObject<S> spawn(S servant);

  /**
   * Creates an object around {@code servant}. A synchronous object registers on its clock and takes
   * part from the next release.
   *
   * @throws IllegalStateException the runtime is shut down
   */
  <S> ActiveObject<S> spawn(S servant, ObjectConfig config);

  /**
   * A reference to the object at {@code address}: the object itself when it lives here, otherwise a
   * reference through the transport (which takes {@link ActiveRef#send(Event) data events}).
   *
   * @throws ObjectStoppedException a local address with no live object
   */
  <S> ActiveRef<S> ref(Address address);

  /** The runtime's figures now. */
  RuntimeStats stats();

  /**
   * Shuts the runtime down: see {@link ShutdownMode}. Idempotent.
   *
   * @return whether everything ended within {@code timeout} and, for DRAIN, whether no queued event
   *     had to be discarded (events whose guard never opened are discarded)
   */
  boolean shutdown(ShutdownMode mode, Duration timeout);

  /** {@code shutdown(ShutdownMode.DRAIN, Duration.ofSeconds(10))}. */
  @Override
  void close();

  /** Settings of a runtime; validated by {@link #build()}. Not thread-safe. */
  final class Builder {
    private static final java.util.concurrent.atomic.AtomicLong UNNAMED =
        new java.util.concurrent.atomic.AtomicLong();

    @Nullable String name;
    int workers = Runtime.getRuntime().availableProcessors();
    ErrorHandler errorHandler = ErrorHandler.logging();
    @Nullable Transport transport;
    TimeSource timeSource = TimeSource.system();
    boolean jmx = true;

    Builder() {}

    /** The runtime's name; default {@code runtime-<n>}. */
    public Builder name(String name) {
      requireNonNull(name, "name");
      if (name.isBlank()) {
        throw new IllegalArgumentException("name must not be blank, was '" + name + "'");
      }
      this.name = name;
      return this;
    }

    /** The number of worker threads for asynchronous objects; default one per core. */
    public Builder workers(int workers) {
      if (workers < 1 || workers > 1024) {
        throw new IllegalArgumentException("workers must be in [1, 1024], was " + workers);
      }
      this.workers = workers;
      return this;
    }

    /** Where failures go; default {@link ErrorHandler#logging()}. */
    public Builder errorHandler(ErrorHandler errorHandler) {
      this.errorHandler = requireNonNull(errorHandler, "errorHandler");
      return this;
    }

    /** How events reach other runtimes; default none (local objects only). */
    public Builder transport(Transport transport) {
      this.transport = requireNonNull(transport, "transport");
      return this;
    }

    /** Where timeouts read time; default {@link TimeSource#system()}. */
    public Builder timeSource(TimeSource timeSource) {
      this.timeSource = requireNonNull(timeSource, "timeSource");
      return this;
    }

    /** Whether to register the runtime's MBean; default true. */
    public Builder jmx(boolean jmx) {
      this.jmx = jmx;
      return this;
    }

    /** A started runtime. */
    public ActiveRuntime build() {
      String n = name != null ? name : "runtime-" + UNNAMED.incrementAndGet();
      return new RuntimeImpl(n, workers, errorHandler, transport, timeSource, jmx);
    }
  }
}

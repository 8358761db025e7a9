package org.armgals.gals;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.List;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.TimeSource;
import org.armgals.active.spi.DeadlinePacer;
import org.armgals.kernel.AdaptationPoint;
import org.armgals.kernel.BehavioralMeta;
import org.armgals.kernel.Entity;
import org.armgals.kernel.EntityOptions;
import org.armgals.kernel.NotificationPolicy;
import org.armgals.kernel.StructuralMeta;

/**
 * A synchronous island (paper §5.2, GALS): reactive entities released together once per period. At
 * each cycle every entity takes the events waiting at the release, then runs its reactions; what
 * one emits at instant {@code k} is seen from {@code k + 1}. Islands talk to each other
 * asynchronously: an event from another island is taken at the receiver's next release.
 *
 * <p>A cycle is a method (docs/architecture.md, convention 3): {@link #step()} runs one on the
 * caller's thread, which is how tests and simulations drive an island (virtual time: instant ×
 * period; the per-cycle trace then depends only on the inputs, not on the number of workers).
 * {@link #start()} hands the island to a runner on a platform thread of its own that releases it
 * every period of real time and applies the {@link OverrunPolicy}.
 *
 * <p>Threading: {@link #step()} is called by one thread at a time and never from inside one of the
 * island's entities, and not at all once the island is started; the other methods may be called
 * from any thread.
 */
public interface Island extends AutoCloseable {

  /**
   * A builder of an island whose entities live in {@code runtime}.
   *
   * @param name the island's name, in its threads' names and its trace
   */
  static Builder builder(String name, ActiveRuntime runtime) {
    return new Builder(name, runtime);
  }

  /** Its name. */
  String name();

  /** The time between two releases. */
  Duration period();

  /**
   * Where in a cycle adaptation requests are applied: {@link AdaptationPoint#BEGIN_OF_CYCLE} (right
   * after the release, before the entities react: a request made before instant {@code k} shapes
   * the reactions of {@code k}; priority to adaptation) or {@link AdaptationPoint#END_OF_CYCLE}
   * (after every entity has reacted: it shapes {@code k + 1}; priority to the deadline). Either way
   * no entity runs while requests are applied.
   */
  AdaptationPoint adaptationPoint();

  /** What a real-time run does after an overrun. */
  OverrunPolicy overrunPolicy();

  /**
   * Creates an entity with {@code state} and one reaction named {@code "main"}; it takes part from
   * the next release.
   *
   * @throws IllegalArgumentException {@code name} is blank or already used in this island
   * @throws IllegalStateException the island is closed
   */
  <S> ReactiveEntity<S> spawn(String name, S state, Reaction<S> main);

  /**
   * Creates a kernel entity of {@code kind} in the synchronous mode on this island (paper §5.3,
   * figure 8: a base-level entity released by the island's clock): it takes its attachment to
   * {@code meta}, and then the stimuli waiting at each release, at the island's releases, and
   * applies the adaptation requests of its behavioral meta at the island's {@link
   * #adaptationPoint()}. It belongs to its kernel ({@link StructuralMeta#instances()}), not to
   * {@link #entities()}: the kernel stops it; once the island is closed it is no longer released.
   *
   * @throws IllegalArgumentException a blank or taken name (in the kernel)
   * @throws IllegalStateException the island is closed
   */
  Entity spawn(
      StructuralMeta<?> kind, String name, BehavioralMeta meta, NotificationPolicy notification);

  /**
   * {@link #spawn(StructuralMeta, String, BehavioralMeta, NotificationPolicy)} with the
   * notification policy, the {@linkplain EntityOptions#program() program} and the {@linkplain
   * EntityOptions#lockStep() lock step} of {@code options}; the object's configuration and the
   * adaptation point are the island's. A robot is such an entity (paper figure 8): its program runs
   * at each release, and in lock step the island's cycle waits at its adaptation point for the
   * entity's meta.
   *
   * @throws IllegalArgumentException a blank or taken name (in the kernel)
   * @throws IllegalStateException the island is closed
   */
  Entity spawn(StructuralMeta<?> kind, String name, BehavioralMeta meta, EntityOptions options);

  /**
   * {@link #spawn(StructuralMeta, String, BehavioralMeta, EntityOptions)} with no behavioral meta
   * yet ({@link StructuralMeta#newEntity(String, EntityOptions)}): for a meta of another runtime to
   * take.
   *
   * @throws IllegalArgumentException a blank or taken name (in the kernel)
   * @throws IllegalStateException the island is closed
   */
  Entity spawn(StructuralMeta<?> kind, String name, EntityOptions options);

  /**
   * Options for a kernel entity of this island, to refine with {@link
   * EntityOptions#withNotification}, {@link EntityOptions#withLockStep} or {@link
   * EntityOptions#withProgram} before {@link #spawn(StructuralMeta, String, BehavioralMeta,
   * EntityOptions)}: a synchronous object on the island's clock, adapting at its point, notifying
   * everything, running free.
   */
  EntityOptions entityOptions();

  /** Its entities, in the order they were spawned. */
  List<ReactiveEntity<?>> entities();

  /**
   * Runs one cycle on the caller's thread: the adaptation point, the release of every entity, and
   * waits until all have reacted.
   *
   * @return the cycle's instant
   * @throws IllegalStateException the island is started, closed, or the caller is one of its
   *     entities
   */
  long step();

  /**
   * Runs {@code cycles} cycles, one after the other, as fast as possible.
   *
   * @throws IllegalArgumentException {@code cycles} is negative
   */
  void step(long cycles);

  /**
   * Starts releasing on real time, one release every period from now. Idempotent.
   *
   * @throws IllegalStateException the island is closed
   */
  void start();

  /** The instant of the last cycle, 0 before the first. */
  long instant();

  /** Its figures now. */
  IslandStats stats();

  /**
   * The per-cycle trace so far, one line per event of a cycle (inputs, trace lines of reactions,
   * adaptations, time-outs, failures), each starting with the island's name and the instant. Empty
   * unless built with {@link Builder#tracing(boolean) tracing}.
   */
  List<String> trace();

  /** The SHA-256 of {@link #trace()} (hex); the hash of nothing unless tracing. */
  String traceHash();

  /** Stops the runner (waiting for the cycle in progress), then every entity. Idempotent. */
  @Override
  void close();

  /** Settings of an island; checked by {@link #build()}. Not thread-safe. */
  final class Builder {
    final String name;
    final ActiveRuntime runtime;
    Duration period = Duration.ofMillis(1);
    AdaptationPoint adaptationPoint = AdaptationPoint.BEGIN_OF_CYCLE;
    OverrunPolicy overrunPolicy = OverrunPolicy.SKIP;
    TimeSource timeSource = TimeSource.system();
    boolean tracing;
    boolean jmx = true;
    int capacity = 1 << 12;

    Builder(String name, ActiveRuntime runtime) {
      this.name = requireNonNull(name, "name");
      this.runtime = requireNonNull(runtime, "runtime");
    }

    /** The time between two releases; default 1 ms. */
    public Builder period(Duration period) {
      this.period = requireNonNull(period, "period");
      return this;
    }

    /**
     * Where adaptation requests are applied; default {@link AdaptationPoint#BEGIN_OF_CYCLE}.
     *
     * @throws IllegalArgumentException {@link AdaptationPoint#ON_ARRIVAL}: an island adapts only
     *     between instants
     */
    public Builder adaptationPoint(AdaptationPoint adaptationPoint) {
      requireNonNull(adaptationPoint, "adaptationPoint");
      if (adaptationPoint == AdaptationPoint.ON_ARRIVAL) {
        throw new IllegalArgumentException(
            "adaptation point of an island must be BEGIN_OF_CYCLE or END_OF_CYCLE, was "
                + adaptationPoint);
      }
      this.adaptationPoint = adaptationPoint;
      return this;
    }

    /** What a real-time run does after an overrun; default {@link OverrunPolicy#SKIP}. */
    public Builder overrunPolicy(OverrunPolicy overrunPolicy) {
      this.overrunPolicy = requireNonNull(overrunPolicy, "overrunPolicy");
      return this;
    }

    /**
     * Where the island reads time to pace releases and to measure cycles and adaptations; default
     * {@link TimeSource#system()}.
     */
    public Builder timeSource(TimeSource timeSource) {
      this.timeSource = requireNonNull(timeSource, "timeSource");
      return this;
    }

    /** Whether to keep the per-cycle trace and its hash; default off (it costs). */
    public Builder tracing(boolean tracing) {
      this.tracing = tracing;
      return this;
    }

    /**
     * Whether to publish the island's figures over JMX ({@link IslandMXBean}) while it is open;
     * default on.
     */
    public Builder jmx(boolean jmx) {
      this.jmx = jmx;
      return this;
    }

    /** The buffer capacity of each entity (it drops its oldest event when full); default 4096. */
    public Builder capacity(int capacity) {
      this.capacity = capacity;
      return this;
    }

    /**
     * The island, not started.
     *
     * @throws IllegalArgumentException the period is not positive, the name is blank, or the
     *     capacity is below 1
     */
    public Island build() {
      if (period.isNegative() || period.isZero()) {
        throw new IllegalArgumentException("period must be > 0, was " + period);
      }
      if (name.isBlank()) {
        throw new IllegalArgumentException("name must not be blank, was '" + name + "'");
      }
      if (capacity < 1) {
        throw new IllegalArgumentException("capacity must be >= 1, was " + capacity);
      }
      return new IslandImpl(this, DeadlinePacer.of(timeSource));
    }
  }
}

package org.armgals.examples.run;

import static java.util.Objects.requireNonNull;

import java.net.URI;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Optional;
import java.util.OptionalLong;
import org.armgals.maam.sim.LegDynamics;

/**
 * The options of {@code armgals run}, checked.
 *
 * @param cycles how many control cycles to run, if given
 * @param simulated how much simulated time to run, if given (at most one of the two)
 * @param period the control period
 * @param seed the seed of every random choice of the run
 * @param atoms the number of atoms, where the example lets it be chosen
 * @param realTime paced to real time, instead of as fast as possible
 * @param broker an external Artemis broker, instead of the embedded one
 * @param out where the run leaves its trace and pictures
 * @param meta where the robots' meta level runs: in their JVM, or in another one over the broker
 * @param warmup paced to real time, how much simulated time to run first on a scratch copy of the
 *     world, in virtual time, and throw away, so that the JVM has compiled what a cycle runs before
 *     the first paced cycle (zero for none; see {@link #DEFAULT_WARMUP})
 * @param legs the simulator's leg model; the robots are tuned for {@link #DEFAULT_LEGS} and may not
 *     walk on the other (decision 0065)
 */
public record RunSettings(
    OptionalLong cycles,
    Optional<Duration> simulated,
    Duration period,
    long seed,
    Optional<Integer> atoms,
    boolean realTime,
    Optional<URI> broker,
    Path out,
    MetaPlace meta,
    Duration warmup,
    LegDynamics legs) {

  /**
   * The warm-up {@code armgals run} gives a run paced to real time unless told otherwise: long
   * enough for the JIT compiler to have compiled the physics, the robots and their meta level,
   * whose first cycles otherwise run several times slower than the period and leave the run behind
   * its schedule for its first seconds.
   */
  public static final Duration DEFAULT_WARMUP = Duration.ofSeconds(5);

  /** The leg model the robots are tuned for, the simulator's default: kinematic legs. */
  public static final LegDynamics DEFAULT_LEGS = LegDynamics.KINEMATIC;

  /** Where a run's meta level runs ({@code --meta}). */
  public enum MetaPlace {
    /** In the robots' JVM: no broker hop, no serialization. */
    LOCAL,
    /** In a JVM of its own, over the broker (embedded over netty on 127.0.0.1 unless given). */
    REMOTE
  }

  /** Settings on the leg model the robots are tuned for. */
  public RunSettings(
      OptionalLong cycles,
      Optional<Duration> simulated,
      Duration period,
      long seed,
      Optional<Integer> atoms,
      boolean realTime,
      Optional<URI> broker,
      Path out,
      MetaPlace meta,
      Duration warmup) {
    this(cycles, simulated, period, seed, atoms, realTime, broker, out, meta, warmup, DEFAULT_LEGS);
  }

  /** Settings without a warm-up, on the leg model the robots are tuned for. */
  public RunSettings(
      OptionalLong cycles,
      Optional<Duration> simulated,
      Duration period,
      long seed,
      Optional<Integer> atoms,
      boolean realTime,
      Optional<URI> broker,
      Path out,
      MetaPlace meta) {
    this(cycles, simulated, period, seed, atoms, realTime, broker, out, meta, Duration.ZERO);
  }

  /** Settings with the meta level in the robots' JVM, without a warm-up. */
  public RunSettings(
      OptionalLong cycles,
      Optional<Duration> simulated,
      Duration period,
      long seed,
      Optional<Integer> atoms,
      boolean realTime,
      Optional<URI> broker,
      Path out) {
    this(cycles, simulated, period, seed, atoms, realTime, broker, out, MetaPlace.LOCAL);
  }

  /** Checks the options against each other and their ranges. */
  public RunSettings {
    requireNonNull(cycles, "cycles");
    requireNonNull(simulated, "simulated");
    requireNonNull(period, "period");
    requireNonNull(atoms, "atoms");
    requireNonNull(broker, "broker");
    requireNonNull(out, "out");
    requireNonNull(meta, "meta");
    requireNonNull(warmup, "warmup");
    requireNonNull(legs, "legs");
    if (cycles.isPresent() && simulated.isPresent()) {
      throw new IllegalArgumentException("give --cycles or --seconds, not both");
    }
    if (cycles.isPresent() && cycles.getAsLong() <= 0) {
      throw new IllegalArgumentException("--cycles must be at least 1, not " + cycles.getAsLong());
    }
    if (simulated.isPresent() && (simulated.get().isNegative() || simulated.get().isZero())) {
      throw new IllegalArgumentException("--seconds must be positive, not " + simulated.get());
    }
    if (period.isNegative() || period.isZero()) {
      throw new IllegalArgumentException("--period must be positive, not " + period);
    }
    if (atoms.isPresent() && atoms.get() < 1) {
      throw new IllegalArgumentException("--atoms must be at least 1, not " + atoms.get());
    }
    if (warmup.isNegative()) {
      throw new IllegalArgumentException("--warmup-seconds must not be negative, not " + warmup);
    }
    if (!warmup.isZero() && !realTime) {
      throw new IllegalArgumentException(
          "--warmup-seconds applies to a run paced to real time (--realtime or --live): a run in"
              + " virtual time has no schedule to fall behind; was "
              + warmup);
    }
  }

  /** These settings, writing into {@code out} instead. */
  public RunSettings withOut(Path out) {
    return new RunSettings(
        cycles, simulated, period, seed, atoms, realTime, broker, out, meta, warmup, legs);
  }

  /** These settings with the meta level at {@code place}. */
  public RunSettings withMeta(MetaPlace place) {
    return new RunSettings(
        cycles, simulated, period, seed, atoms, realTime, broker, out, place, warmup, legs);
  }

  /** These settings paced to real time, with the same warm-up. */
  public RunSettings pacedToRealTime() {
    return new RunSettings(
        cycles, simulated, period, seed, atoms, true, broker, out, meta, warmup, legs);
  }

  /** These settings with {@code warmup} (zero for none). */
  public RunSettings withWarmup(Duration warmup) {
    return new RunSettings(
        cycles, simulated, period, seed, atoms, realTime, broker, out, meta, warmup, legs);
  }

  /**
   * The settings of the warm-up that precedes a run with these settings: the same world and seed,
   * {@code cycles} of them, in virtual time with the meta level in the robots' JVM, writing into
   * {@code scratch}.
   */
  public RunSettings warmUp(long cycles, Path scratch) {
    return new RunSettings(
        OptionalLong.of(cycles),
        Optional.empty(),
        period,
        seed,
        atoms,
        false,
        broker,
        scratch,
        MetaPlace.LOCAL,
        Duration.ZERO,
        legs);
  }
}

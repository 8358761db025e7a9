package org.armgals.examples.sim;

import java.io.PrintStream;
import java.time.Duration;
import org.armgals.examples.run.Example;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Simulation;

/**
 * An example robot on the simulator: the scene it runs in, and the controllers (and meta levels)
 * that drive its atoms. {@link #run} steps the simulation in virtual time, or paced to real time,
 * and leaves the trace and the pictures in the settings' output directory.
 *
 * <p>Implementations are stateless: everything a run changes lives in the {@link Crew} that {@link
 * #start} answers, so {@link #run} may be called more than once. Same settings, same trace, bit for
 * bit: a crew draws every random choice from {@link RunSettings#seed()}.
 */
public interface SimExample extends Example {

  /**
   * The scene of a run with {@code settings}.
   *
   * @throws IllegalArgumentException if a setting does not apply (say {@code --atoms} to a robot of
   *     a fixed shape), naming it and what would
   */
  Scene scene(RunSettings settings);

  /** How much simulated time a run lasts when the settings give neither cycles nor seconds. */
  Duration defaultDuration();

  /**
   * Whether the example talks to a broker, so that {@code --broker} applies; false unless it
   * spreads over several runtimes.
   */
  default boolean usesBroker() {
    return false;
  }

  /**
   * Its meta level for a run with {@code settings} ({@link MetaLevel}), if it has one: what {@code
   * --meta local|remote} places in the robots' JVM or in another. Empty by default.
   */
  default java.util.Optional<MetaLevel> metaLevel(RunSettings settings) {
    return java.util.Optional.empty();
  }

  /**
   * Installs the controllers of {@code sim}'s atoms (with {@link Simulation#setController}) and
   * whatever meta level watches them, before the first cycle; called on the thread that will run
   * the simulation.
   *
   * @param journal where the crew tells the adaptations it makes, and why
   */
  Crew start(Simulation sim, RunSettings settings, Journal journal);

  /**
   * Runs it as {@code armgals run --live} does: paced to real time times {@code speed} (whatever
   * the settings say of pacing), telling {@code watcher} what happens as it does.
   *
   * @throws IllegalArgumentException {@code speed} is not a finite number above zero
   */
  default Summary run(RunSettings settings, PrintStream out, RunWatcher watcher, double speed) {
    if (!(speed > 0) || Double.isInfinite(speed)) {
      throw new IllegalArgumentException("--speed must be a finite number above 0, was " + speed);
    }
    RunSettings paced = settings.pacedToRealTime();
    return SimRun.run(
        this, paced, out, java.util.Objects.requireNonNull(watcher, "watcher"), speed);
  }

  /** Runs it as {@code armgals run} does: see {@link SimRun}. */
  @Override
  default Summary run(RunSettings settings, PrintStream out) {
    return SimRun.run(this, settings, out);
  }
}

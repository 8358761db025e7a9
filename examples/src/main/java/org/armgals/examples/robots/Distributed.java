package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.Locale;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.sim.BrokerLogin;
import org.armgals.examples.sim.Crew;
import org.armgals.examples.sim.Journal;
import org.armgals.examples.sim.SimExample;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;

/**
 * {@code distributed}: a chain of atoms, each run by its own robot in its own JVM, on an island of
 * its own clock, all talking to the world through one Artemis broker (GALS, paper §5.2: locally
 * synchronous islands composed asynchronously; and location transparency: the robot is the same
 * {@code AbstractRobot} whose body happens to be in another process), with the paper's battery
 * example as its meta level across JVMs (§2.3, figure 8).
 *
 * <p>The process of {@code armgals run} holds the world (the simulation), the meta level and,
 * unless {@code --broker} names one, an embedded broker on a free port of 127.0.0.1. Each cycle the
 * world sends every atom its sensor readings and waits for the leg targets its robot answers; an
 * answer that does not come in time is a missed cycle. In lock step (the default) the world waits
 * up to ten seconds, so the run is the same as if the robots ran in the world's own cycle; with
 * {@code --realtime} it waits one period and goes on with the commands it has. The credentials of
 * an external broker, if it needs any, come from {@code ARMGALS_BROKER_USER} and {@code
 * ARMGALS_BROKER_PASSWORD}.
 *
 * <p>The meta level ({@link DistributedMeta}) is a behavioral meta-entity of a kernel of the
 * world's runtime, in a JVM apart from every atom's: it takes each atom's robot by name, hears its
 * threshold meta-events only, and asks an atom whose battery fell under half for a gentler stroke.
 * It is already apart from the robots, so {@code --meta remote} does not apply.
 */
public final class Distributed implements SimExample {
  /** The atoms of a chain, when {@code --atoms} is not given. */
  static final int DEFAULT_ATOMS = 3;

  /**
   * Energy of an atom's battery, J: the stroke of {@link DistributedGait#SWING} rad draws 1.4 to
   * 2.2 W, so each atom's falls under half within the run's 6 s, and the gentler one lasts the run.
   */
  static final double BATTERY_CAPACITY = 10;

  static final int MIN_ATOMS = 2;
  static final int MAX_ATOMS = 6;

  /** Centre to centre along the chain: two kernel radii and two legs, tips touching. */
  private static final double SPACING = 0.22;

  private final double capacity;

  /** The chain, each atom on a battery of {@value #BATTERY_CAPACITY} J. */
  public Distributed() {
    this(BATTERY_CAPACITY);
  }

  /** The chain, each atom on a battery of {@code capacity} J. */
  Distributed(double capacity) {
    if (!(capacity > 0)) {
      throw new IllegalArgumentException("battery capacity " + capacity + " J: expected > 0");
    }
    this.capacity = capacity;
  }

  @Override
  public String name() {
    return "distributed";
  }

  @Override
  public String summary() {
    return "a chain whose atoms each run in their own JVM on their own clock, through one broker";
  }

  @Override
  public Scene scene(RunSettings settings) {
    requireNonNull(settings, "settings");
    if (settings.meta() == RunSettings.MetaPlace.REMOTE) {
      throw new IllegalArgumentException(
          "--meta remote: 'distributed' runs its meta level in the world's JVM, apart from every"
              + " atom's JVM already; leave --meta out");
    }
    int atoms = settings.atoms().orElse(DEFAULT_ATOMS);
    if (atoms < MIN_ATOMS || atoms > MAX_ATOMS) {
      throw new IllegalArgumentException(
          "--atoms "
              + atoms
              + ": 'distributed' runs a chain of "
              + MIN_ATOMS
              + " to "
              + MAX_ATOMS
              + " atoms, one JVM each");
    }
    StringBuilder text = new StringBuilder("scene distributed-chain").append(atoms).append('\n');
    text.append(String.format(Locale.ROOT, "param batteryCapacity %s%n", capacity));
    for (int i = 0; i < atoms; i++) {
      // Rolled 45° about the chain's axis: the atom lies on its -z and -y legs, where it rests.
      text.append(
          String.format(Locale.ROOT, "atom %d %.2f 0 0.080 1 0 0 45%n", i + 1, SPACING * i));
    }
    for (int i = 1; i < atoms; i++) {
      text.append("bond ").append(i).append(":+x ").append(i + 1).append(":-x\n");
    }
    return Scenes.parse(text.toString());
  }

  @Override
  public Duration defaultDuration() {
    return Duration.ofSeconds(6);
  }

  @Override
  public boolean usesBroker() {
    return true;
  }

  @Override
  public Crew start(Simulation sim, RunSettings settings, Journal journal) {
    requireNonNull(sim, "sim");
    requireNonNull(settings, "settings");
    requireNonNull(journal, "journal");
    return DistributedCrew.start(
        sim,
        settings.broker().map(Object::toString).orElse(null),
        BrokerLogin.fromEnvironment(),
        settings,
        journal);
  }
}

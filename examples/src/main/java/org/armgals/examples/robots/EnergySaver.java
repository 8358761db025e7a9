package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.Locale;
import org.armgals.examples.cli.RunSettings;
import org.armgals.examples.sim.Crew;
import org.armgals.examples.sim.Journal;
import org.armgals.examples.sim.SimExample;
import org.armgals.kernel.Threshold;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;

/**
 * {@code energy}: the paper's battery example on a moving atom (§2.3, §4, §5.4). A lone atom,
 * standing as a tripod, walks with a fast gait that drains its small battery. Its behavioral meta
 * level ({@link EnergyMeta}, a framework {@code BMetaRobot} judging notifications with the kernel's
 * selector filters) drops the robot's energy events while the battery is above 30%; on the
 * threshold meta-event it subscribes to them (its filter changes at run time) and adapts the robot
 * to a saving gait, with smaller strokes and a lower torque limit, by a {@code changeModule}
 * request. It lasts longer than the same robot without its meta level ({@link #withoutMetaLevel}).
 *
 * <p>Stateless: each {@link #start} makes a new robot and meta level.
 */
public final class EnergySaver implements SimExample {

  /** Energy of the atom's battery, J: the fast gait drains it in about ten simulated seconds. */
  static final double BATTERY_CAPACITY = 40;

  /** The threshold meta-event: below 30% of a full battery; above again over 40%. */
  static final Threshold LOW = new Threshold("low-battery", "fraction", 0.30, 0.40);

  private static final int ATOM = 1;

  private final double capacity;
  private final boolean metaLevel;

  /** The robot with its meta level, on a battery of {@value #BATTERY_CAPACITY} J. */
  public EnergySaver() {
    this(BATTERY_CAPACITY, true);
  }

  EnergySaver(double capacity, boolean metaLevel) {
    if (!(capacity > 0)) {
      throw new IllegalArgumentException("battery capacity " + capacity + " J: expected > 0");
    }
    this.capacity = capacity;
    this.metaLevel = metaLevel;
  }

  /**
   * The same robot on the same battery, without its meta level: it keeps the fast gait. Named
   * {@code energy-without-meta}, to compare with {@code energy}.
   */
  public static EnergySaver withoutMetaLevel() {
    return withoutMetaLevel(BATTERY_CAPACITY);
  }

  static EnergySaver withoutMetaLevel(double capacity) {
    return new EnergySaver(capacity, false);
  }

  @Override
  public String name() {
    return metaLevel ? "energy" : "energy-without-meta";
  }

  @Override
  public String summary() {
    if (!metaLevel) {
      return "the energy robot without its meta level, to compare: it keeps its fast gait";
    }
    return "the battery example: the meta level ignores energy events until a threshold"
        + " meta-event, then switches to a saving gait; it lasts longer";
  }

  @Override
  public Scene scene(RunSettings settings) {
    requireNonNull(settings, "settings");
    if (settings.atoms().isPresent()) {
      throw new IllegalArgumentException(
          "'energy' is one atom: --atoms does not apply (leave it out)");
    }
    return Scenes.parse(
        String.format(
            Locale.ROOT,
            "scene energy\nparam batteryCapacity %s\natom %d 0 0 0.07 tripod\n",
            capacity,
            ATOM));
  }

  @Override
  public Duration defaultDuration() {
    return Duration.ofSeconds(30);
  }

  @Override
  public Crew start(Simulation sim, RunSettings settings, Journal journal) {
    return begin(sim, settings, journal);
  }

  /** {@link #start}, answering the crew with what a test looks at. */
  EnergyCrew begin(Simulation sim, RunSettings settings, Journal journal) {
    requireNonNull(sim, "sim");
    requireNonNull(journal, "journal");
    double period = settings.period().toNanos() / 1e9;
    EnergyRobot robot;
    EnergyMeta meta = null;
    if (metaLevel) {
      meta = new EnergyMeta(ATOM, journal, period);
      robot = new EnergyRobot(sim.body(ATOM), sim::timeNanos, period, capacity, LOW, meta);
    } else {
      robot = new EnergyRobot(sim.body(ATOM), sim::timeNanos, period, capacity, LOW);
    }
    EnergyCrew crew = new EnergyCrew(sim, robot, meta, capacity);
    sim.setController(ATOM, (atom, cycle) -> crew.cycle());
    return crew;
  }
}

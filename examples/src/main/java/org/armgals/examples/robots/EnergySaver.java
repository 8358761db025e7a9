package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.Crew;
import org.armgals.examples.sim.Journal;
import org.armgals.examples.sim.MetaLevel;
import org.armgals.examples.sim.Reflection;
import org.armgals.examples.sim.SimExample;
import org.armgals.gals.Island;
import org.armgals.kernel.AdaptationPoint;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.NotificationPolicy;
import org.armgals.kernel.StructuralMeta;
import org.armgals.kernel.Threshold;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.sim.spi.Controller;
import org.armgals.maam.spi.Body;
import org.armgals.representation.p.PState;
import org.jspecify.annotations.Nullable;

/**
 * {@code energy}: the paper's battery example on a moving atom (§2.3, §4, §5.4). A lone atom,
 * standing as a tripod, walks with a fast gait that drains its small battery. The robot is a kernel
 * entity whose kernel watches the threshold {@link #LOW} on its observed battery; its behavioral
 * meta-entity ({@link EnergyMeta}, in the robot's JVM or another) hears only threshold meta-events
 * while the battery is above 30% (its filter, a JMS selector, drops every state); on the threshold
 * meta-event it takes the states too (its filter changes at run time) and adapts the robot to a
 * saving gait, with smaller strokes and a lower torque limit, by a {@code changeModule} request. It
 * lasts longer than the same robot without its meta level ({@link #withoutMetaLevel}).
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

  /** Its meta level, unless made {@link #withoutMetaLevel}. */
  @Override
  public Optional<MetaLevel> metaLevel(RunSettings settings) {
    return metaLevel ? Optional.of(new Level()) : Optional.empty();
  }

  /** The energy robot's meta level: the same code in the robot's JVM or another. */
  static final class Level implements MetaLevel {
    private @Nullable EnergyMeta meta;

    @Override
    public Map<String, StructuralMeta<PState>> kinds(Kernel kernel) {
      return Map.of(ROBOT, EnergyRobot.kind(kernel));
    }

    @Override
    public List<Watch> watches(MetaNotes notes) {
      EnergyMeta m = new EnergyMeta(notes);
      meta = m;
      return List.of(new Watch(m, List.of(ROBOT), EnergyMeta.THRESHOLDS_ONLY));
    }

    @Override
    public List<Summary.Entry> figures() {
      EnergyMeta m = requireNonNull(meta, "meta");
      return List.of(
          new Summary.Entry("gait switches asked for", Integer.toString(m.switches())),
          new Summary.Entry("states followed after the threshold", Long.toString(m.followed())),
          new Summary.Entry(
              "saving gait's draw, as the meta measured it",
              Double.isNaN(m.savingWatts())
                  ? "not measured"
                  : String.format(Locale.ROOT, "%.2f W", m.savingWatts())),
          new Summary.Entry("meta's filter at the end", m.filter()));
    }

    /** The meta-entity of the local run; null before {@link #watches}. */
    @Nullable EnergyMeta meta() {
      return meta;
    }
  }

  /** The energy robot's name, its kernel entity's. */
  static final String ROBOT = "energy";

  @Override
  public Crew start(Simulation sim, RunSettings settings, Journal journal) {
    return begin(sim, settings, journal);
  }

  /** {@link #start}, answering the crew with what a test looks at. */
  EnergyCrew begin(Simulation sim, RunSettings settings, Journal journal) {
    requireNonNull(sim, "sim");
    requireNonNull(settings, "settings");
    requireNonNull(journal, "journal");
    double period = settings.period().toNanos() / 1e9;
    Body body = sim.body(ATOM);
    EnergyRobot robot = new EnergyRobot(body, sim::timeNanos, period, capacity);
    Level level = metaLevel ? new Level() : null;
    Reflection reflection = Reflection.open(sim, settings, name(), level, journal);
    try {
      Island island = reflection.island(ROBOT, AdaptationPoint.END_OF_CYCLE);
      reflection.start(robot, ATOM, island, NotificationPolicy.statesOnly().watching(LOW));
      EnergyCrew crew = new EnergyCrew(sim, robot, level, reflection, capacity);
      sim.setController(ATOM, Controller.driving(body, () -> crew.cycle(island)));
      reflection.ready();
      return crew;
    } catch (RuntimeException | Error e) {
      reflection.close();
      throw e;
    }
  }
}

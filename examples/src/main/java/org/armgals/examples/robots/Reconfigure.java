package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
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
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.sim.spi.Controller;
import org.armgals.maam.spi.Body;
import org.armgals.representation.p.PState;
import org.jspecify.annotations.Nullable;

/**
 * {@code reconfigure}: the terrain changes, the molecule changes shape, and the software
 * reconfigures its schemas with it (paper §1: the shape provides for the function, and a physical
 * reconfiguration is paralleled by a software one).
 *
 * <p>A chain of four atoms crawls along x with {@link ObstacleRobot}'s alternating tripod, the
 * front atom beating the rhythm and each atom passing it to the one behind through their bond
 * (neighbour messages). It enters a corridor: its front atom's side legs see a wall on each side.
 * The meta level ({@link ReconfigureMeta}, a behavioral meta-entity taking every atom, in their JVM
 * or another) splits the chain in two pairs: it adds a {@code detach} schema to the two atoms of
 * the middle bond, whose actuators release it through the body SPI; when both sense the bond gone,
 * the rear pair's front atom swaps its {@code follow} schema for a {@code pace} schema (a head now)
 * and the front pair's rear atom removes its {@code relay} (no one behind it). Both pairs crawl on,
 * each a molecule with its own head and rhythm.
 */
public final class Reconfigure implements SimExample {

  @Override
  public String name() {
    return "reconfigure";
  }

  @Override
  public String summary() {
    return "a chain of 4 atoms enters a corridor; the meta level splits it into two pairs and"
        + " swaps the schemas: a new head, a relay removed";
  }

  @Override
  public Scene scene(RunSettings settings) {
    requireNonNull(settings, "settings");
    if (settings.atoms().isPresent()) {
      throw new IllegalArgumentException(
          "'reconfigure' is a chain of "
              + ReconfigureTuning.ATOMS
              + " atoms that splits into two pairs: --atoms does not apply to it (try"
              + " 'caterpillar')");
    }
    return Scenes.parse(sceneText(true));
  }

  @Override
  public Duration defaultDuration() {
    return Duration.ofSeconds(12);
  }

  @Override
  public Crew start(Simulation sim, RunSettings settings, Journal journal) {
    return startCrew(sim, settings, journal);
  }

  /** Its meta level: {@code bmchain} ({@link ReconfigureMeta}) takes every atom. */
  @Override
  public Optional<MetaLevel> metaLevel(RunSettings settings) {
    return Optional.of(new Level(settings.period().toNanos()));
  }

  /** The names of the atoms' robots, rear first: atoms 1 to {@value ReconfigureTuning#ATOMS}. */
  static List<String> robots() {
    return java.util.stream.IntStream.rangeClosed(1, ReconfigureTuning.ATOMS)
        .mapToObj(id -> "atom-" + id)
        .toList();
  }

  /** The chain's meta level: the same code in the robots' JVM or another. */
  static final class Level implements MetaLevel {
    private final long periodNanos;
    private @Nullable ReconfigureMeta meta;

    Level(long periodNanos) {
      this.periodNanos = periodNanos;
    }

    @Override
    public Map<String, StructuralMeta<PState>> kinds(Kernel kernel) {
      StructuralMeta<PState> kind = ReconfigureAtom.kind(kernel);
      Map<String, StructuralMeta<PState>> kinds = new LinkedHashMap<>();
      robots().forEach(robot -> kinds.put(robot, kind));
      return kinds;
    }

    @Override
    public List<Watch> watches(MetaNotes notes) {
      ReconfigureMeta m = new ReconfigureMeta(robots(), periodNanos);
      meta = m;
      return List.of(new Watch(m, robots(), ""));
    }

    @Override
    public List<Summary.Entry> figures() {
      ReconfigureMeta m = requireNonNull(meta, "meta");
      return List.of(
          new Summary.Entry(
              "split",
              m.splitAt() < 0
                  ? "no"
                  : String.format(Locale.ROOT, "at %.2f s (%s)", m.splitAt() / 1e9, m.stage())));
    }

    /** The meta-entity of a local run; null before {@link #watches}. */
    @Nullable ReconfigureMeta meta() {
      return meta;
    }
  }

  /** Starts the chain's robots and their meta level. */
  ReconfigureCrew startCrew(Simulation sim, RunSettings settings, Journal journal) {
    requireNonNull(sim, "sim");
    requireNonNull(settings, "settings");
    requireNonNull(journal, "journal");
    long period = settings.period().toNanos();
    Level level = new Level(period);
    Reflection reflection = Reflection.open(sim, settings, name(), level, journal);
    try {
      List<Integer> ids = sim.atomIds();
      List<ReconfigureAtom> robots = new ArrayList<>();
      for (int i = 0; i < ids.size(); i++) {
        int id = ids.get(i);
        Body body = sim.body(id);
        ReconfigureAtom robot =
            new ReconfigureAtom(id, body, sim::timeNanos, period, i == ids.size() - 1, i == 0);
        Island island = reflection.island(robot.name(), AdaptationPoint.END_OF_CYCLE);
        reflection.start(robot, id, island, NotificationPolicy.statesOnly());
        robots.add(robot);
        sim.setController(id, Controller.driving(body, () -> reflection.step(island)));
      }
      reflection.ready();
      return new ReconfigureCrew(sim, robots, level, reflection);
    } catch (RuntimeException | Error e) {
      reflection.close();
      throw e;
    }
  }

  /**
   * The chain along x, each atom turned 45° about x so it stands on two feet, as {@link
   * ObstacleRobot}'s; the corridor's two walls ahead, either side of the path, unless {@code
   * corridor} is false (open ground all the way, to compare).
   */
  static String sceneText(boolean corridor) {
    StringBuilder s = new StringBuilder("scene reconfigure\n");
    s.append("param maxTorque ").append(ObstacleGait.MAX_TORQUE).append('\n');
    double wallY = ReconfigureTuning.CORRIDOR_HALF_WIDTH + ReconfigureTuning.WALL_THICKNESS / 2;
    for (int side : corridor ? new int[] {1, -1} : new int[0]) {
      s.append(
          String.format(
              Locale.ROOT,
              "box %s %s %s %s %s %s%n",
              ReconfigureTuning.CORRIDOR_START + ReconfigureTuning.CORRIDOR_LENGTH / 2,
              side * wallY,
              ReconfigureTuning.WALL_HEIGHT / 2,
              ReconfigureTuning.CORRIDOR_LENGTH,
              ReconfigureTuning.WALL_THICKNESS,
              ReconfigureTuning.WALL_HEIGHT));
    }
    StandingChain.append(s, ReconfigureTuning.ATOMS, ReconfigureTuning.REAR_START);
    return s.toString();
  }
}

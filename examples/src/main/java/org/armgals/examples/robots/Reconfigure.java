package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.armgals.examples.cli.RunSettings;
import org.armgals.examples.sim.Crew;
import org.armgals.examples.sim.Journal;
import org.armgals.examples.sim.SimExample;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;

/**
 * {@code reconfigure}: the terrain changes, the molecule changes shape, and the software
 * reconfigures its schemas with it (paper §1: the shape provides for the function, and a physical
 * reconfiguration is paralleled by a software one).
 *
 * <p>A chain of four atoms crawls along x with {@link ObstacleRobot}'s alternating tripod, the
 * front atom beating the rhythm and each atom passing it to the one behind through their bond
 * (neighbour messages). It enters a corridor: its front atom's side legs see a wall on each side.
 * The meta level ({@link ReconfigureMeta}) splits the chain in two pairs: it adds a {@code detach}
 * schema to the two atoms of the middle bond, whose actuators release it through the body SPI; when
 * both sense the bond gone, the rear pair's front atom swaps its {@code follow} schema for a {@code
 * pace} schema (a head now) and the front pair's rear atom removes its {@code relay} (no one behind
 * it). Both pairs crawl on, each a molecule with its own head and rhythm.
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

  /** Starts the chain's robots and their meta level. */
  ReconfigureCrew startCrew(Simulation sim, RunSettings settings, Journal journal) {
    requireNonNull(sim, "sim");
    requireNonNull(settings, "settings");
    requireNonNull(journal, "journal");
    long period = settings.period().toNanos();
    ReconfigureMeta meta = new ReconfigureMeta(journal, period);
    List<Integer> ids = sim.atomIds();
    List<ReconfigureAtom> robots = new ArrayList<>();
    for (int i = 0; i < ids.size(); i++) {
      int id = ids.get(i);
      ReconfigureAtom robot =
          new ReconfigureAtom(
              id, sim.body(id), sim::timeNanos, period, i == ids.size() - 1, i == 0);
      meta.watch(id, robot);
      robots.add(robot);
      sim.setController(id, (body, cycle) -> robot.cycle());
    }
    return new ReconfigureCrew(sim, robots, meta);
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

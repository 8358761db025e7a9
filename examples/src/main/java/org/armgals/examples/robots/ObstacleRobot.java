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
 * {@code obstacle}: a chain of three atoms crawls into a low step, and its meta level gets it over.
 *
 * <p>Each atom runs its own MAAM robot ({@link ObstacleAtom}): a {@code cruise} schema (an
 * alternating-tripod crawl) and, on the front atom, a {@code climb} reflex whose careful stride
 * suppresses cruise's while its feeler leg sees the step: subsumption (paper §5). The careful
 * stride is not enough: the feet drag against the step's face and the chain pushes without gain.
 * The behavioral meta level ({@link ObstacleMeta}, a {@code BMetaRobot}) watches the front atom's
 * progress in the cycle reports, notices the loop (no progress for two seconds), and adds a {@code
 * lift-front} schema to every atom's robot at its adaptation point: the atom at the step's edge
 * swings its feet up and is carried over by its neighbours, the others keep crawling. Each
 * adaptation is told to the journal, so it shows in the trace, the time line and the summary.
 */
public final class ObstacleRobot implements SimExample {

  @Override
  public String name() {
    return "obstacle";
  }

  @Override
  public String summary() {
    return "a chain of 3 atoms meets a step; climb subsumes cruise; the meta level sees no"
        + " progress and adds a lift-front schema";
  }

  @Override
  public Scene scene(RunSettings settings) {
    requireNonNull(settings, "settings");
    if (settings.atoms().isPresent()) {
      throw new IllegalArgumentException(
          "'obstacle' is a chain of "
              + ObstacleGait.ATOMS
              + " atoms: --atoms does not apply to it (try 'caterpillar')");
    }
    return Scenes.parse(sceneText());
  }

  @Override
  public Duration defaultDuration() {
    return Duration.ofSeconds(20);
  }

  @Override
  public Crew start(Simulation sim, RunSettings settings, Journal journal) {
    return start(sim, settings, journal, true);
  }

  /** Starts the chain's robots, with or without their meta level (to compare). */
  ObstacleCrew start(Simulation sim, RunSettings settings, Journal journal, boolean withMeta) {
    requireNonNull(sim, "sim");
    requireNonNull(settings, "settings");
    requireNonNull(journal, "journal");
    ObstacleMeta meta = new ObstacleMeta(journal);
    List<Integer> ids = sim.atomIds();
    List<ObstacleAtom> robots = new ArrayList<>();
    long period = settings.period().toNanos();
    for (int i = 0; i < ids.size(); i++) {
      int id = ids.get(i);
      boolean front = i == ids.size() - 1;
      ObstacleAtom robot =
          new ObstacleAtom(
              i, TrackedBody.of(sim, id), sim::timeNanos, period, front && withMeta ? meta : null);
      meta.watch(id, robot);
      robots.add(robot);
      sim.setController(id, (body, cycle) -> robot.cycle());
    }
    return new ObstacleCrew(sim, robots, meta);
  }

  /** The chain, along x, turned 45° about x so each atom stands on two feet; the step ahead. */
  static String sceneText() {
    StringBuilder s = new StringBuilder("scene obstacle\n");
    s.append("param maxTorque ").append(ObstacleGait.MAX_TORQUE).append('\n');
    s.append(
        String.format(
            Locale.ROOT,
            "box %s 0 %s %s 1 %s%n",
            ObstacleGait.STEP_FACE + ObstacleGait.STEP_DEPTH / 2,
            ObstacleGait.STEP_HEIGHT / 2,
            ObstacleGait.STEP_DEPTH,
            ObstacleGait.STEP_HEIGHT));
    StandingChain.append(
        s,
        ObstacleGait.ATOMS,
        ObstacleGait.FRONT_START - (ObstacleGait.ATOMS - 1) * ObstacleGait.SPACING);
    return s.toString();
  }
}

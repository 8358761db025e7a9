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
import org.armgals.representation.p.PState;
import org.jspecify.annotations.Nullable;

/**
 * {@code obstacle}: a chain of three atoms crawls into a low step, and its meta level gets it over.
 *
 * <p>Each atom runs its own MAAM robot ({@link ObstacleAtom}): a {@code cruise} schema (an
 * alternating-tripod crawl) and, on the front atom, a {@code climb} reflex whose careful stride
 * suppresses cruise's while its feeler leg sees the step: subsumption (paper §5). The careful
 * stride is not enough: the feet drag against the step's face and the chain pushes without gain.
 * The behavioral meta level ({@link ObstacleMeta}, a behavioral meta-entity taking every atom's
 * robot, in their JVM or another) watches the front atom's progress in its states, notices the loop
 * (no progress for two seconds), and asks every atom for a {@code lift-front} schema of their
 * kind's catalog, applied at their adaptation points: the atom at the step's edge swings its feet
 * up and is carried over by its neighbours, the others keep crawling. Each adaptation is told to
 * the journal, so it shows in the trace, the time line and the summary.
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

  /** Its meta level: {@code bmchain} ({@link ObstacleMeta}) takes every atom. */
  @Override
  public Optional<MetaLevel> metaLevel(RunSettings settings) {
    return Optional.of(new Level());
  }

  /** The chain's meta level: the same code in the robots' JVM or another. */
  static final class Level implements MetaLevel {
    private @Nullable ObstacleMeta meta;

    @Override
    public Map<String, StructuralMeta<PState>> kinds(Kernel kernel) {
      StructuralMeta<PState> kind = ObstacleAtom.kind(kernel);
      Map<String, StructuralMeta<PState>> kinds = new LinkedHashMap<>();
      ObstacleMeta.robots(ObstacleGait.ATOMS).forEach(robot -> kinds.put(robot, kind));
      return kinds;
    }

    @Override
    public List<Watch> watches(MetaNotes notes) {
      List<String> robots = ObstacleMeta.robots(ObstacleGait.ATOMS);
      ObstacleMeta m = new ObstacleMeta(robots.get(robots.size() - 1));
      meta = m;
      return List.of(new Watch(m, robots, ""));
    }

    @Override
    public List<Summary.Entry> figures() {
      return List.of(
          new Summary.Entry(
              "lift-front asked for", Boolean.toString(requireNonNull(meta, "meta").adapted())));
    }
  }

  /** Starts the chain's robots, with or without their meta level (to compare). */
  ObstacleCrew start(Simulation sim, RunSettings settings, Journal journal, boolean withMeta) {
    requireNonNull(sim, "sim");
    requireNonNull(settings, "settings");
    requireNonNull(journal, "journal");
    List<Integer> ids = sim.atomIds();
    List<ObstacleAtom> robots = new ArrayList<>();
    long period = settings.period().toNanos();
    Reflection reflection =
        Reflection.open(
            sim, settings, name(), withMeta ? metaLevel(settings).orElseThrow() : null, journal);
    try {
      for (int i = 0; i < ids.size(); i++) {
        int id = ids.get(i);
        boolean front = i == ids.size() - 1;
        TrackedBody body = TrackedBody.of(sim, id);
        ObstacleAtom robot = new ObstacleAtom(i, body, sim::timeNanos, period);
        Island island = reflection.island(robot.name(), AdaptationPoint.END_OF_CYCLE);
        reflection.start(
            robot,
            id,
            island,
            front ? NotificationPolicy.statesOnly() : NotificationPolicy.quiet());
        robots.add(robot);
        sim.setController(id, body.driving(() -> reflection.step(island)));
      }
      reflection.ready();
      return new ObstacleCrew(sim, robots, reflection);
    } catch (RuntimeException | Error e) {
      reflection.close();
      throw e;
    }
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

package org.armgals.examples.robots;

import java.util.List;
import java.util.Locale;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.Crew;
import org.armgals.examples.sim.Reflection;
import org.armgals.maam.Schema;
import org.armgals.maam.sim.Simulation;

/** One run of {@link ObstacleRobot}: the chain's robots and their reflective side. */
final class ObstacleCrew implements Crew {
  private final Simulation sim;
  private final List<ObstacleAtom> robots;
  private final Reflection reflection;

  ObstacleCrew(Simulation sim, List<ObstacleAtom> robots, Reflection reflection) {
    this.sim = sim;
    this.robots = List.copyOf(robots);
    this.reflection = reflection;
  }

  @Override
  public java.util.Optional<Reflection> reflection() {
    return java.util.Optional.of(reflection);
  }

  /** The robots, rear first. */
  List<ObstacleAtom> robots() {
    return robots;
  }

  /** Where the molecule's centre is along the path now (m): the mean of its kernels. */
  double centre() {
    return StandingChain.centreX(sim, sim.atomIds());
  }

  @Override
  public List<Summary.Entry> figures() {
    double centre = centre();
    return List.of(
        new Summary.Entry(
            "step edge", String.format(Locale.ROOT, "x = %.2f m", ObstacleGait.STEP_FACE)),
        new Summary.Entry("centre at the end", String.format(Locale.ROOT, "x = %.3f m", centre)),
        new Summary.Entry("atoms past the step's face", pastTheFace() + " of " + robots.size()),
        new Summary.Entry("schemas at the end", String.join(", ", schemaNames())));
  }

  /** How many atoms have their kernel beyond the step's face: the chain is over when all are. */
  private long pastTheFace() {
    return sim.atomIds().stream()
        .filter(id -> sim.sensors(id).position().x() > ObstacleGait.STEP_FACE)
        .count();
  }

  private List<String> schemaNames() {
    return robots.get(robots.size() - 1).metaRobot().schemas().stream().map(Schema::name).toList();
  }
}

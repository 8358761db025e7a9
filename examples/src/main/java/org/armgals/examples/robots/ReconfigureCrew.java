package org.armgals.examples.robots;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.TreeSet;
import java.util.stream.Collectors;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.Crew;
import org.armgals.examples.sim.Reflection;
import org.armgals.maam.Schema;
import org.armgals.maam.sim.LegSensors;
import org.armgals.maam.sim.Simulation;

/** One run of {@link Reconfigure}: the chain's robots, its meta level and reflective side. */
final class ReconfigureCrew implements Crew {
  private final Simulation sim;
  private final List<ReconfigureAtom> robots;
  private final Reconfigure.Level level;
  private final Reflection reflection;

  ReconfigureCrew(
      Simulation sim,
      List<ReconfigureAtom> robots,
      Reconfigure.Level level,
      Reflection reflection) {
    this.sim = sim;
    this.robots = List.copyOf(robots);
    this.level = level;
    this.reflection = reflection;
  }

  @Override
  public java.util.Optional<Reflection> reflection() {
    return java.util.Optional.of(reflection);
  }

  /** The robots, rear first. */
  List<ReconfigureAtom> robots() {
    return robots;
  }

  /** The meta level of a local run. */
  ReconfigureMeta meta() {
    return java.util.Objects.requireNonNull(level.meta(), "meta");
  }

  /** Bonds between atoms, from their binding sensors. */
  int bonds() {
    int bound = 0;
    for (int id : sim.atomIds()) {
      for (LegSensors leg : sim.sensors(id).legs()) {
        if (leg.neighbour().isPresent()) {
          bound++;
        }
      }
    }
    return bound / 2;
  }

  /** The molecules, each the ids of its atoms in order, from the binding sensors. */
  List<List<Integer>> molecules() {
    List<List<Integer>> molecules = new ArrayList<>();
    TreeSet<Integer> left = new TreeSet<>(sim.atomIds());
    while (!left.isEmpty()) {
      TreeSet<Integer> molecule = new TreeSet<>();
      List<Integer> todo = new ArrayList<>(List.of(left.first()));
      while (!todo.isEmpty()) {
        int id = todo.remove(todo.size() - 1);
        if (molecule.add(id)) {
          for (LegSensors leg : sim.sensors(id).legs()) {
            leg.neighbour().ifPresent(todo::add);
          }
        }
      }
      left.removeAll(molecule);
      molecules.add(List.copyOf(molecule));
    }
    return molecules;
  }

  /** Where the atoms {@code ids} are along the path now (m): the mean of their kernels. */
  double centre(List<Integer> ids) {
    return StandingChain.centreX(sim, ids);
  }

  @Override
  public List<Summary.Entry> figures() {
    List<Summary.Entry> figures = new ArrayList<>();
    figures.add(
        new Summary.Entry(
            "molecules at the end",
            molecules().stream()
                .map(m -> String.format(Locale.ROOT, "%s at x = %.3f m", m, centre(m)))
                .collect(Collectors.joining("; "))));
    figures.add(new Summary.Entry("bonds at the end", Integer.toString(bonds())));
    for (ReconfigureAtom robot : robots) {
      figures.add(
          new Summary.Entry(
              "schemas of " + robot.name(),
              robot.metaRobot().schemas().stream()
                  .map(Schema::name)
                  .collect(Collectors.joining(", "))));
    }
    return figures;
  }
}

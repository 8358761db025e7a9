package org.armgals.examples.robots;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.OptionalDouble;
import org.armgals.examples.cli.Summary;
import org.armgals.examples.robots.EnergyModules.Stepper;
import org.armgals.examples.sim.Crew;
import org.armgals.maam.Schedule;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.spi.Atom;
import org.jspecify.annotations.Nullable;

/**
 * One run of the {@link EnergySaver}: its robot, its meta level if it has one, and when the battery
 * ran out. Used on the simulation's thread.
 */
final class EnergyCrew implements Crew {
  private final Simulation sim;
  private final EnergyRobot robot;
  private final @Nullable EnergyMeta meta;
  private double emptyAt = Double.NaN;

  EnergyCrew(Simulation sim, EnergyRobot robot, @Nullable EnergyMeta meta) {
    this.sim = sim;
    this.robot = robot;
    this.meta = meta;
  }

  /** One control cycle: the robot's, then a look at the battery it left. */
  void cycle() {
    robot.cycle();
    if (Double.isNaN(emptyAt) && robot.body().read(Atom.BATTERY) <= 0) {
      emptyAt = sim.timeNanos() / 1e9;
    }
  }

  /** Simulated time at which the battery was first seen empty, if it was. */
  OptionalDouble emptyAt() {
    return Double.isNaN(emptyAt) ? OptionalDouble.empty() : OptionalDouble.of(emptyAt);
  }

  /** The gait the robot runs now. */
  EnergyGait gait() {
    Schedule schedule = robot.schedule();
    return schedule.modules().stream()
        .filter(Stepper.class::isInstance)
        .map(m -> ((Stepper) m).gait())
        .findFirst()
        .orElseThrow();
  }

  @Nullable EnergyMeta meta() {
    return meta;
  }

  EnergyRobot robot() {
    return robot;
  }

  @Override
  public List<Summary.Entry> figures() {
    List<Summary.Entry> figures = new ArrayList<>();
    figures.add(new Summary.Entry("gait", gait().name()));
    figures.add(
        new Summary.Entry(
            "battery empty at",
            emptyAt().isPresent()
                ? String.format(Locale.ROOT, "%.2f s", emptyAt().getAsDouble())
                : "not yet"));
    if (meta != null) {
      figures.add(
          new Summary.Entry("energy events dropped by the meta's filter", "" + meta.dropped()));
      figures.add(
          new Summary.Entry("energy events followed after the threshold", "" + meta.followed()));
      figures.add(new Summary.Entry("meta's filter", meta.filter().expression()));
    } else {
      figures.add(new Summary.Entry("meta level", "none"));
    }
    return figures;
  }
}

package org.armgals.examples.robots;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalDouble;
import org.armgals.examples.robots.EnergyModules.Stepper;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.Crew;
import org.armgals.examples.sim.Reflection;
import org.armgals.gals.Island;
import org.armgals.maam.Schedule;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.spi.Atom;
import org.jspecify.annotations.Nullable;

/**
 * One run of the {@link EnergySaver}: its robot, its meta level if it has one, its reflective side,
 * and when the battery ran out. Used on the simulation's thread.
 */
final class EnergyCrew implements Crew {
  private final Simulation sim;
  private final EnergyRobot robot;
  private final EnergySaver.@Nullable Level level;
  private final Reflection reflection;
  private final double capacity;
  private double emptyAt = Double.NaN;
  private EnergyGait gait = EnergyGait.FAST;
  private double switchedAt = Double.NaN;
  private double joulesAtSwitch;
  private double seconds;
  private double joules;

  EnergyCrew(
      Simulation sim,
      EnergyRobot robot,
      EnergySaver.@Nullable Level level,
      Reflection reflection,
      double capacity) {
    this.sim = sim;
    this.robot = robot;
    this.level = level;
    this.reflection = reflection;
    this.capacity = capacity;
    this.joules = capacity;
  }

  /**
   * One control cycle: the robot's, then a look at the battery (read at the cycle's start) and at
   * the gait it left, for the summary's figures.
   */
  void cycle(Island island) {
    reflection.step(island);
    seconds = sim.timeNanos() / 1e9;
    if (Double.isNaN(emptyAt)) {
      joules = robot.body().read(Atom.BATTERY);
      if (joules <= 0) {
        emptyAt = seconds;
      }
    }
    EnergyGait now = gait();
    if (!now.equals(gait)) {
      gait = now;
      switchedAt = seconds;
      joulesAtSwitch = joules;
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

  /** The meta level of a local run; null for the robot without one. */
  @Nullable EnergyMeta meta() {
    return level == null ? null : level.meta();
  }

  @Override
  public Optional<Reflection> reflection() {
    return Optional.of(reflection);
  }

  EnergyRobot robot() {
    return robot;
  }

  /** What a gait drew, and how long a full battery would last at that draw. */
  private Summary.Entry draw(EnergyGait drawing, double used, double during) {
    double watts = during > 0 ? used / during : 0;
    return new Summary.Entry(
        drawing.name() + " gait's draw",
        String.format(
            Locale.ROOT,
            "%.2f W over %.2f s (a full battery of %.0f J lasts %.1f s at it)",
            watts,
            during,
            capacity,
            watts > 0 ? capacity / watts : Double.POSITIVE_INFINITY));
  }

  @Override
  public List<Summary.Entry> figures() {
    List<Summary.Entry> figures = new ArrayList<>();
    figures.add(new Summary.Entry("gait", gait().name()));
    double end = Double.isNaN(emptyAt) ? seconds : emptyAt;
    if (Double.isNaN(switchedAt)) {
      figures.add(draw(EnergyGait.FAST, capacity - joules, end));
    } else {
      figures.add(draw(EnergyGait.FAST, capacity - joulesAtSwitch, switchedAt));
      figures.add(draw(EnergyGait.SAVING, joulesAtSwitch - joules, end - switchedAt));
    }
    figures.add(
        new Summary.Entry(
            "battery empty at",
            emptyAt().isPresent()
                ? String.format(Locale.ROOT, "%.2f s", emptyAt().getAsDouble())
                : "not yet"));
    return figures;
  }
}

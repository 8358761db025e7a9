package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.util.List;

/**
 * What a robot tells its {@link BMetaRobot} at the end of each cycle (paper §5.4, step 1 of the
 * adaptation protocol): enough for the meta to keep a model of the robot.
 *
 * @param robot the robot's name
 * @param cycle the robot's cycle number, from 1
 * @param nanoTime the cycle's time, from the robot's time source
 * @param emissions every signal emitted in the cycle, after suppression, in slot order
 * @param applied the adaptations applied since the previous report
 * @param rejected the adaptations rejected since the previous report
 * @param moduleErrors the modules that failed in this cycle, by name
 */
public record CycleReport(
    String robot,
    long cycle,
    long nanoTime,
    List<Emission> emissions,
    List<Adaptation> applied,
    List<Rejected> rejected,
    List<String> moduleErrors) {

  /** Copies the lists. */
  public CycleReport {
    requireNonNull(robot, "robot");
    emissions = List.copyOf(emissions);
    applied = List.copyOf(applied);
    rejected = List.copyOf(rejected);
    moduleErrors = List.copyOf(moduleErrors);
  }

  /**
   * The signal on {@code port} this cycle.
   *
   * @param port an output port
   * @param signal what its readers saw
   */
  public record Emission(PortRef port, Signal signal) {

    /** Checks for nulls. */
    public Emission {
      requireNonNull(port, "port");
      requireNonNull(signal, "signal");
    }
  }

  /**
   * An adaptation the robot's {@link MetaRobot} refused.
   *
   * @param adaptation what was asked
   * @param reason the refusal's message
   */
  public record Rejected(Adaptation adaptation, String reason) {

    /** Checks for nulls. */
    public Rejected {
      requireNonNull(adaptation, "adaptation");
      requireNonNull(reason, "reason");
    }
  }
}

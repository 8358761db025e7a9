package org.armgals.examples.robots;

import org.armgals.maam.Signal;

/** The signals of {@link ObstacleRobot}'s modules. */
final class ObstacleSignals {
  private ObstacleSignals() {}

  /** The metronome's beat: the robot's cycle number, from 0. */
  record Tick(long cycle) implements Signal {}

  /** Where the atom is along the path (m), from its odometry. */
  record Position(double x) implements Signal {}

  /** The feeler sees something this near ahead (m): the step. */
  record StepAhead(double distance) implements Signal {}

  /**
   * How the feet move this cycle: the gait's phase (rad), the sweep and lift amplitudes (rad), or
   * {@code carried}: feet swung out and up, the atom borne by its neighbours.
   */
  record Stride(double phase, double sweep, double lift, boolean carried) implements Signal {}
}

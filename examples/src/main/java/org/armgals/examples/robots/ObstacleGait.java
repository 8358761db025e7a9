package org.armgals.examples.robots;

import org.armgals.maam.spi.LegAngles;

/**
 * The physical constants of {@link ObstacleRobot}, in one place: its molecule's layout, its crawl,
 * its feeler and the step it meets, all found by short runs on the simulator.
 *
 * <p>Each atom of the chain is turned 45° about x, so it stands on two feet, its −z and −y legs,
 * spread across the path; its ±x legs bind it to its neighbours. The crawl is an alternating
 * tripod: three feet push (their tips sweep back) while the other three swing forward, lifted.
 */
final class ObstacleGait {
  /** Atoms in the chain, bound +x to −x. */
  static final int ATOMS = 3;

  /** Distance between the kernels of two bound atoms (m): two radii and two legs. */
  static final double SPACING = 0.22;

  /** Height of a kernel's centre when it stands on two feet at 45° (m). */
  static final double STANDING_HEIGHT = 0.11 * Math.cos(Math.PI / 4) + 0.002;

  /** Where the front atom starts (m). */
  static final double FRONT_START = 0.62;

  /** The step: its near face (m), height (m) and depth (m); it spans the whole path. */
  static final double STEP_FACE = 0.75;

  static final double STEP_HEIGHT = 0.01;
  static final double STEP_DEPTH = 0.4;

  /** The motors' torque limit (N·m): the carried atom hangs from its neighbours' bonds. */
  static final double MAX_TORQUE = 1.0;

  /** Cruise: sweep amplitude (rad), lift (rad), frequency (Hz), time to reach full stride (s). */
  static final double SWEEP = 0.4;

  static final double LIFT = 0.3;
  static final double FREQUENCY = 1.5;
  static final double RAMP = 0.5;

  /** Climb: the careful stride's lift (rad), higher than cruise's. */
  static final double CLIMB_LIFT = 0.5;

  /** Lift-front: how far a carried atom swings its feet out and up (rad, the cone's edge). */
  static final double CARRY = 0.52;

  /** The window around the step's edge in which an atom is carried (m, behind and beyond). */
  static final double CARRY_BEHIND = 0.05;

  static final double CARRY_BEYOND = 0.10;

  /**
   * The feeler: the front atom's +x leg turned by these joint angles (rad) points about 20° down,
   * so its proximity ray meets the ground some 11 cm ahead of its tip, and the step's face or top
   * nearer than {@link #NEAR} (m) when the step is close.
   */
  static final double FEELER_A1 = -0.25;

  static final double FEELER_A2 = 0.23;
  static final double NEAR = 0.098;

  /** The joint's sign conventions for the two feet, found by experiment. */
  static final double SWEEP_MZ = 1;

  static final double SWEEP_MY = -1;
  static final double LIFT_MZ = -1;
  static final double LIFT_MY = 1;

  private ObstacleGait() {}

  /**
   * The framework's elevation and azimuth of a leg whose joint is turned by {@code a1} then {@code
   * a2} (rad): the leg points at {@code (sin a2, -sin a1 cos a2, cos a1 cos a2)} in the frame (axis
   * 1, axis 2, cone axis), as the simulator's body maps it.
   */
  static LegAngles joint(double a1, double a2) {
    double u = Math.sin(a2);
    double v = -Math.sin(a1) * Math.cos(a2);
    double w = Math.cos(a1) * Math.cos(a2);
    double elevation = Math.atan2(Math.hypot(u, v), w);
    double azimuth = elevation == 0 ? 0 : Math.atan2(v, u);
    return new LegAngles(elevation, azimuth);
  }
}

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

  /**
   * The step: its near face (m), height (m) and depth (m); it spans the whole path. Two
   * centimetres: a stiff leg's stride lifted 0.3 rad clears one, and the chain would simply walk up
   * it; a kernel's underside (3 cm up) clears two. Deep enough that the chain does not walk off its
   * far end in a run.
   */
  static final double STEP_FACE = 0.75;

  static final double STEP_HEIGHT = 0.02;
  static final double STEP_DEPTH = 1.0;

  /** The motors' torque limit (N·m): the carried atom hangs from its neighbours' bonds. */
  static final double MAX_TORQUE = 1.0;

  /**
   * Cruise: sweep amplitude (rad), lift (rad), frequency (Hz), time to reach full stride (s). About
   * 5 cm/s: the chain is stiff, and the faster it meets the step's face the harder the jolt its
   * bonds take.
   */
  static final double SWEEP = 0.25;

  static final double LIFT = 0.3;
  static final double FREQUENCY = 1.0;
  static final double RAMP = 0.5;

  /**
   * Climb: the careful stride's sweep (rad), short so that the front feet meet the step slowly, and
   * its lift (rad), higher than cruise's but short of the step's two centimetres.
   */
  static final double CLIMB_SWEEP = 0.1;

  static final double CLIMB_LIFT = 0.35;

  /**
   * The most a foot's joint angle moves in one control cycle (rad): more than the gait's own
   * strides ask (at most 0.016), far less than the servo could (0.06), so that a change of stride
   * is eased.
   */
  static final double FOOT_SLEW = 0.02;

  /** Lift-front: how far a carried atom swings its feet out and up (rad, the cone's edge). */
  static final double CARRY = 0.52;

  /** The window around the step's edge in which an atom is carried (m, behind and beyond). */
  static final double CARRY_BEHIND = 0.05;

  static final double CARRY_BEYOND = 0.10;

  /**
   * The feeler: the front atom's +x leg turned by these joint angles (rad) points about 26° down,
   * so its proximity ray meets the ground some 12 cm from its tip, 21 cm ahead of the kernel, and
   * the step's top nearer than {@link #NEAR} (m) once the step is that close.
   */
  static final double FEELER_A1 = -0.34;

  static final double FEELER_A2 = 0.31;
  static final double NEAR = 0.10;

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

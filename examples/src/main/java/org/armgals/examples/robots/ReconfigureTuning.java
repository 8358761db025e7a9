package org.armgals.examples.robots;

/**
 * The physical constants of {@link Reconfigure}: its chain, its crawl, the corridor it meets, and
 * the side legs that see the corridor's walls. The crawl is {@link ObstacleRobot}'s alternating
 * tripod, at a pace of its own: with no step to meet, it goes twice as fast.
 */
final class ReconfigureTuning {
  /** Atoms in the chain, bound +x to −x; the chain splits between the second and the third. */
  static final int ATOMS = 4;

  /** Where the rear atom starts (m); the others follow along +x, {@link ObstacleGait#SPACING}. */
  static final double REAR_START = 0.0;

  /** The corridor: where its walls begin (m), how long they are, how far from the path (m). */
  static final double CORRIDOR_START = 0.85;

  static final double CORRIDOR_LENGTH = 3.0;
  static final double CORRIDOR_HALF_WIDTH = 0.15;

  /** The walls' thickness and height (m): high enough for the side legs' rays to meet. */
  static final double WALL_THICKNESS = 0.02;

  static final double WALL_HEIGHT = 0.3;

  /**
   * A side leg sees a wall when its proximity ray (it points 45° up, across the path) meets
   * something nearer than this (m); on open ground it meets nothing within range.
   */
  static final double WALL_NEAR = 0.2;

  /** How long the head must see both walls before the meta level splits the chain (s). */
  static final double CORRIDOR_SECONDS = 0.2;

  /** Crawl: sweep amplitude (rad), lift (rad), frequency (Hz), time to reach full stride (s). */
  static final double SWEEP = 0.4;

  static final double LIFT = 0.3;
  static final double FREQUENCY = 1.5;
  static final double RAMP = 0.5;

  /**
   * The most a foot's joint angle moves in one control cycle (rad): above the crawl's own 0.038, so
   * it eases only a jump.
   */
  static final double FOOT_SLEW = 0.05;

  private ReconfigureTuning() {}

  /** The gait's phase advance in one control period of {@code periodNanos} (rad). */
  static double advance(long periodNanos) {
    return 2 * Math.PI * FREQUENCY * (periodNanos / 1e9);
  }
}

package org.armgals.examples.robots;

/**
 * The physical constants of {@link Reconfigure}: its chain, the corridor it meets, and the side
 * legs that see the corridor's walls. The crawl itself is {@link ObstacleRobot}'s alternating
 * tripod, with {@link ObstacleGait}'s constants, unchanged.
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

  private ReconfigureTuning() {}

  /** The gait's phase advance in one control period of {@code periodNanos} (rad). */
  static double advance(long periodNanos) {
    return 2 * Math.PI * ObstacleGait.FREQUENCY * (periodNanos / 1e9);
  }
}

package org.armgals.examples.robots;

import java.util.List;
import org.armgals.maam.spi.Leg;

/**
 * The walker's physical constants, in one place: they depend on the atom's model (cone half-angle
 * 30°, friction 0.8, the tripod pose), and a lighter or stiffer atom may want others.
 */
final class WalkerTuning {

  private WalkerTuning() {}

  /** The legs the atom stands on, resting as a tripod. */
  static final List<Leg> GROUND = List.of(Leg.MX, Leg.MY, Leg.MZ);

  /**
   * Where each ground leg is in its circle when the gait starts, in turns: −x, then −z a third of a
   * turn later, then −y (with the circling's sense, the order that does not turn the atom round).
   */
  static final double[] OFFSETS = {0, 2.0 / 3, 1.0 / 3};

  /** The sense the tips circle in: +1 or -1. */
  static final double TURN = 1;

  /**
   * The direction the gait carries the atom on the ground, radians from +x (measured: the tips'
   * circling shuffles the tripod towards −x and −y, about 36° off −x).
   */
  static final double HEADING = 1.2 * Math.PI;

  /** Turns of the legs per second. */
  static final double FREQUENCY = 3;

  /**
   * How far the legs tilt from their cones' axes as they circle, radians: the tips then go round at
   * 6.6 rad/s, about what the servos give.
   */
  static final double AMPLITUDE = 0.35;

  /** How far behind its target a leg may be before the gait waits for it, radians. */
  static final double TRACKING = 0.3;

  /** How far the atom may lean from its resting attitude before the balance reflex acts. */
  static final double LEAN_LIMIT = 0.35;

  /** How long the balance reflex keeps the gait suppressed after it last acted, seconds. */
  static final double BALANCE_HOLD = 0.3;
}

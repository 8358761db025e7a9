package org.armgals.examples.robots;

import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;

/**
 * The caterpillar's physical constants, in one place: they depend on the atom's model (cone
 * half-angle 30°, leg and kernel sizes), and a lighter or stiffer atom may want others.
 */
final class CaterpillarTuning {

  private CaterpillarTuning() {}

  /**
   * Seconds per step: long enough that the swing, a quarter of it, brings a foot forward by the
   * longest stride without outrunning its servo's 6 rad/s much.
   */
  static final double PERIOD = 1.0;

  /**
   * How far behind the segment ahead each segment steps, in steps: three quarters, so a quarter
   * ahead: the wave runs from the tail to the head, one segment a quarter step, and a segment
   * swings while the one ahead of it is early in its stance, its feet under or before its kernel. A
   * stiff chain then always rests with its weight between its feet; with the wave the other way
   * round, a chain of three tips onto its lifted end and shakes its bonds loose.
   */
  static final double LAG = 0.75;

  /** The stride the head starts with, radians: short, so that the meta level has work to do. */
  static final double START_STRIDE = 0.2;

  /** The longest stride the meta level asks for: the cone's half-angle, less a margin. */
  static final double MAX_STRIDE = 0.5;

  /** How much the meta level lengthens the stride each time. */
  static final double STRIDE_STEP = 0.1;

  /**
   * The fraction of a step the foot is on the ground: three quarters, so that with the wave a
   * quarter step per segment only one segment swings at a time.
   */
  static final double DUTY = 0.75;

  /** How the segments stand: turned about the chain's axis so that two legs slant to the ground. */
  static final double ROLL_DEGREES = 45;

  /** The kernel's height standing so, metres: where it rests, so that it does not drop. */
  static final double HEIGHT = 0.080;

  /**
   * Where {@code foot} points for a tilt of {@code along} radians along the chain and {@code out}
   * radians outwards: -z tilts along x about its first axis and outwards about its second, -y the
   * other way round.
   */
  static LegAngles foot(Leg foot, double along, double out) {
    double u = foot == Leg.MZ ? ALONG_SIGN * along : OUT_SIGN * out;
    double v = foot == Leg.MZ ? OUT_SIGN * out : ALONG_SIGN * along;
    double elevation = Math.hypot(u, v);
    return new LegAngles(elevation, elevation == 0 ? 0 : Math.atan2(v, u));
  }

  /** The sign taking a tilt along the chain to the foot's frame. */
  static final double ALONG_SIGN = 1;

  /** The sign taking an outward tilt to the foot's frame. */
  static final double OUT_SIGN = 1;

  /** Progress per step below which the meta level lengthens the stride, metres. */
  static final double SLOW_STEP = 0.05;

  /** Steps the meta level waits after an adaptation before judging again (dwell time). */
  static final int DWELL_STEPS = 2;
}

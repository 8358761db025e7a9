package org.armgals.examples.robots;

import org.armgals.maam.spi.LegAngles;

/**
 * The crawl of {@link Distributed}'s chain: each atom lies rolled 45° about the chain's axis on its
 * two lower legs ({@code -z} and {@code -y}), which row in opposite phase. A leg's stroke pushes
 * its tip straight through the cone's axis from the front to the back (the leg is longest, so it
 * bears the weight); its return goes round the cone's edge (the leg is shorter, so it slides back
 * unloaded). Atom {@code i} of {@code n} is {@code i / n} of a stroke behind the head. Found by
 * trial on the simulator: the chain crawls towards {@code -x}, about 2.5 cm/s with two atoms.
 */
final class DistributedGait {
  /** One stroke and return, in seconds of simulated time. */
  static final double PERIOD = 0.5;

  /**
   * How far a leg swings from its cone's axis at first, rad: the amplitude of its stroke (the cone
   * allows 30°, {@link #MAX_SWING}).
   */
  static final double SWING = 0.45;

  /** The widest swing a leg's cone allows, rad (30°). */
  static final double MAX_SWING = Math.PI / 6;

  /** Where the front of the stroke is, as an azimuth, for the {@code -z} leg. */
  static final double FRONT_MZ = Math.PI;

  /** The same for the {@code -y} leg, whose axis 1 is z. */
  static final double FRONT_MY = -Math.PI / 2;

  private DistributedGait() {}

  /** The phase, in [0, 1), of atom {@code index} of {@code count} at {@code seconds}. */
  static double phase(double seconds, int index, int count) {
    double phase = seconds / PERIOD + (double) index / count;
    return phase - Math.floor(phase);
  }

  /**
   * Where a leg whose stroke starts at azimuth {@code front} and swings {@code swing} rad from its
   * cone's axis points at {@code phase}.
   */
  static LegAngles leg(double phase, double front, double swing) {
    if (phase < 0.5) {
      double along = swing * (1 - 4 * phase); // from +swing (front) to -swing (back)
      return new LegAngles(Math.abs(along), wrap(along >= 0 ? front : front + Math.PI));
    }
    return new LegAngles(swing, wrap(front + Math.PI + 2 * Math.PI * (phase - 0.5)));
  }

  /**
   * Checks that {@code swing} is a stroke's amplitude a leg's cone allows.
   *
   * @throws IllegalArgumentException it is not in (0, {@link #MAX_SWING}], naming it
   */
  static double checkSwing(double swing) {
    if (!(swing > 0 && swing <= MAX_SWING)) {
      throw new IllegalArgumentException(
          "swing " + swing + " rad: expected in (0, " + MAX_SWING + "] (a leg's cone is 30°)");
    }
    return swing;
  }

  private static double wrap(double angle) {
    double a = Math.IEEEremainder(angle, 2 * Math.PI);
    return Math.max(-Math.PI, Math.min(Math.PI, a));
  }
}

package org.armgals.examples.robots;

import org.armgals.maam.spi.LegAngles;

/**
 * The crawl of {@link Distributed}'s chain: each atom lies rolled 45° about the chain's axis on its
 * two lower legs ({@code -z} and {@code -y}), which row in opposite phase. A leg's stroke pushes
 * its tip from the front to the back under the kernel, level with the ground (it bears the weight);
 * its return goes round the outer half of the cone's edge (the leg is lifted, so it comes back
 * unloaded). Atom {@code i} of {@code n} is {@code i / n} of a stroke behind the head. Found by
 * trial on the simulator: the chain crawls towards {@code -x}, about 12 cm/s with two to six atoms.
 */
final class DistributedGait {
  /** One stroke and return, in seconds of simulated time. */
  static final double PERIOD = 0.8;

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

  /** The azimuth that tilts the {@code -z} leg outwards, away from the chain: up. */
  static final double OUT_MZ = Math.PI / 2;

  /** The same for the {@code -y} leg. */
  static final double OUT_MY = 0;

  private DistributedGait() {}

  /** The phase, in [0, 1), of atom {@code index} of {@code count} at {@code seconds}. */
  static double phase(double seconds, int index, int count) {
    double phase = seconds / PERIOD + (double) index / count;
    return phase - Math.floor(phase);
  }

  /**
   * Where a leg whose stroke starts at azimuth {@code front}, whose outward tilt is at azimuth
   * {@code out}, and which swings {@code swing} rad from its cone's axis points at {@code phase}.
   * In the first half its tip goes from the front to the back level with the ground ({@link
   * StandingChain#level}: a little inwards at both ends, where the leg is tilted most); in the
   * second it comes back round the outer half of the cone's edge, {@code swing} from the axis, so
   * lifted. The leg is never farther than {@code swing} from its axis.
   */
  static LegAngles leg(double phase, double front, double out, double swing) {
    double reach = reach(swing);
    double along;
    double outwards;
    if (phase < 0.5) {
      along = reach * (1 - 4 * phase); // from the front to the back
      outwards = StandingChain.level(along);
    } else {
      // Round the edge, from the back end of the stroke over the outer side to its front end.
      double below = Math.atan2(-StandingChain.level(reach), reach);
      double angle = Math.PI + below - (Math.PI + 2 * below) * 2 * (phase - 0.5);
      along = swing * Math.cos(angle);
      outwards = swing * Math.sin(angle);
    }
    double u = along * Math.cos(front) + outwards * Math.cos(out);
    double v = along * Math.sin(front) + outwards * Math.sin(out);
    double elevation = Math.hypot(u, v);
    return new LegAngles(elevation, elevation == 0 ? 0 : Math.atan2(v, u));
  }

  /** How far along the chain a level stroke reaches whose ends are {@code swing} from the axis. */
  private static double reach(double swing) {
    double along = swing;
    for (int i = 0; i < 12; i++) {
      double level = StandingChain.level(along);
      along = Math.sqrt(swing * swing - level * level);
    }
    return along;
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
}

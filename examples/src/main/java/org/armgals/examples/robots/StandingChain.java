package org.armgals.examples.robots;

import java.util.List;
import java.util.Locale;
import org.armgals.maam.sim.Simulation;

/**
 * The molecule of {@link ObstacleRobot} and {@link Reconfigure}: a chain of atoms along x, each
 * turned 45° about x so that it stands on two feet (its −z and −y legs), bound {@code i:+x} to
 * {@code i+1:-x}, {@link ObstacleGait#SPACING} apart. The caterpillar and the distributed chain
 * stand the same way, and sweep their feet level with {@link #level}.
 */
final class StandingChain {
  private StandingChain() {}

  /** Appends the scene lines of {@code atoms} atoms, ids 1 on, the rear one at {@code rearX}. */
  static void append(StringBuilder scene, int atoms, double rearX) {
    for (int i = 0; i < atoms; i++) {
      double x = rearX + i * ObstacleGait.SPACING;
      scene.append(
          String.format(
              Locale.ROOT,
              "atom %d %s 0 %s 1 0 0 45%n",
              i + 1,
              (float) x,
              (float) ObstacleGait.STANDING_HEIGHT));
    }
    for (int i = 1; i < atoms; i++) {
      scene.append("bond ").append(i).append(":+x ").append(i + 1).append(":-x\n");
    }
  }

  /**
   * The outward tilt (negative: inwards) that keeps a foot tilted {@code along} radians along the
   * chain at the height it has at rest, so that a foot in stance sweeps level with the ground: a
   * tilt along the chain raises the tip by {@code 1 - cos}, a tilt inwards lowers it, and a stiff
   * chain whose feet rise and fall as they sweep is lifted and dropped by them, jolting its bonds.
   * For a foot slanting at 45°, its height stays when {@code cos e - sin e · out / e = 1}, {@code
   * e} the whole tilt {@code hypot(along, out)}: solved by fixed-point steps (each gains about two
   * digits).
   */
  static double level(double along) {
    double out = 0;
    for (int i = 0; i < 12; i++) {
      double e = Math.hypot(along, out);
      if (e == 0) {
        return 0;
      }
      out = (Math.cos(e) - 1) / (Math.sin(e) / e);
    }
    return out;
  }

  /** Where the atoms {@code ids} of {@code sim} are along the path now (m): their kernels' mean. */
  static double centreX(Simulation sim, List<Integer> ids) {
    return ids.stream().mapToDouble(id -> sim.sensors(id).position().x()).average().orElseThrow();
  }
}

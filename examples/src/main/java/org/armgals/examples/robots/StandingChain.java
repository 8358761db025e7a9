package org.armgals.examples.robots;

import java.util.List;
import java.util.Locale;
import org.armgals.maam.sim.Simulation;

/**
 * The molecule of {@link ObstacleRobot} and {@link Reconfigure}: a chain of atoms along x, each
 * turned 45° about x so that it stands on two feet (its −z and −y legs), bound {@code i:+x} to
 * {@code i+1:-x}, {@link ObstacleGait#SPACING} apart.
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

  /** Where the atoms {@code ids} of {@code sim} are along the path now (m): their kernels' mean. */
  static double centreX(Simulation sim, List<Integer> ids) {
    return ids.stream()
        .mapToDouble(id -> sim.atom(id).sensors().position().x())
        .average()
        .orElseThrow();
  }
}

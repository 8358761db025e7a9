package org.armgals.maam.sim;

import static org.armgals.maam.sim.TestScenes.joints;
import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import org.armgals.maam.sim.spi.Controller;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Atoms walk with their legs: a leg whose tip touches the ground and sweeps one way pushes its atom
 * the other way, within friction (docs/simulator.md, "How an atom moves"). The gaits here are the
 * ones the guide describes: a slip-stick wave, where at any time one leg returns while the others
 * push, so the pushing legs' friction wins.
 */
class LocomotionTest {

  /**
   * The sweep of a leg at {@code phase} (in periods): from +1 to -1 (pushing) for all but the last
   * {@code back} of the period, then quickly back to +1.
   */
  static double sweep(double phase, double back) {
    double p = phase - Math.floor(phase);
    double push = 1 - back;
    return p < push ? 1 - 2 * p / push : -1 + 2 * (p - push) / back;
  }

  /** How far a leg lifts at {@code phase}: 0 while it pushes, up to 1 mid-return. */
  static double lift(double phase, double back) {
    double p = phase - Math.floor(phase);
    double push = 1 - back;
    return p < push ? 0 : Math.sin(Math.PI * (p - push) / back);
  }

  /**
   * A lone tripod walks along the world's +x: each ground leg sweeps its tip along x (mapped into
   * the atom's frame), a third of a period apart.
   */
  static Controller tripodWalk(double periodSeconds, double amplitude) {
    Leg[] ground = {Leg.MX, Leg.MY, Leg.MZ};
    return (body, cycle) -> {
      AtomSensors s = joints(body).sensors();
      double t = s.timeNanos() / 1e9;
      double[] x = inverseRotate(s.orientation(), 1, 0, 0);
      for (int i = 0; i < ground.length; i++) {
        Leg leg = ground[i];
        double k = amplitude * sweep(t / periodSeconds + i / 3.0, 0.25);
        // Turning angle 1 moves the tip along leg × axis1, angle 2 along leg × axis2.
        double[] d = {leg.x(), leg.y(), leg.z()};
        double[] by1 = cross(d, axis1(leg));
        double[] by2 = cross(d, axis2(leg));
        joints(body).setLegTarget(leg, k * dot(x, by1), k * dot(x, by2));
      }
    };
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void aLoneTripodPushingWithItsGroundLegsWalks(LegDynamics dynamics) {
    try (Simulation s =
        Simulation.builder(Scenes.builtIn("single"))
            .legDynamics(dynamics)
            .controller(1, tripodWalk(0.6, 0.3))
            .build()) {
      s.runFor(Duration.ofMillis(300));
      Vec3 start = s.sensors(1).position();
      s.runFor(Duration.ofSeconds(3));
      Vec3 end = s.sensors(1).position();
      assertThat(end.x() - start.x()).as("metres walked along x").isGreaterThan(0.03);
      assertThat(Math.abs(end.y() - start.y())).isLessThan(end.x() - start.x());
      assertThat(s.sensors(1).tilt()).isLessThan(0.3);
    }
  }

  /**
   * A chain of four atoms along x, each turned 45° about x so that it stands on its -y and -z legs,
   * crawls along +x when a wave runs along its ground legs: each atom in turn lifts its two ground
   * legs and swings them forward while the others push back. With either leg model: a kinematic
   * chain is stiffer, and its bound legs give way slowly (decision 0047), so its bonds hold.
   */
  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void aBoundChainCrawlsWithAWaveOfLegMotionsAndKeepsItsBonds(LegDynamics dynamics) {
    StringBuilder scene = new StringBuilder("scene crawl\n");
    double reach = AtomParams.defaults().reach();
    for (int i = 1; i <= 4; i++) {
      scene.append("atom ").append(i).append(' ').append((i - 1) * 2 * reach);
      scene.append(" 0 0.08 1 0 0 45\n");
    }
    for (int i = 1; i < 4; i++) {
      scene.append("bond ").append(i).append(":+x ").append(i + 1).append(":-x\n");
    }
    try (Simulation s =
        Simulation.builder(Scenes.parse(scene.toString()))
            .legDynamics(dynamics)
            .controllers(
                id ->
                    (body, cycle) -> {
                      double phase = joints(body).sensors().timeNanos() / 1e9 / 0.8 + id / 4.0;
                      double k = 0.3 * sweep(phase, 0.25);
                      double up = 0.25 * lift(phase, 0.25);
                      // -z's angle 2 moves its tip along +x and angle 1 down; -y's angle 1 along
                      // -x and angle 2 up (the atom turned 45° about x).
                      joints(body).setLegTarget(Leg.MZ, -up, k);
                      joints(body).setLegTarget(Leg.MY, -k, up);
                    })
            .build()) {
      s.runFor(Duration.ofMillis(300));
      double start = s.sensors(1).position().x();
      s.runFor(Duration.ofSeconds(4));
      double end = s.sensors(1).position().x();
      assertThat(end - start).as("metres crawled along x").isGreaterThan(0.05);
      for (int i = 1; i < 4; i++) {
        assertThat(s.sensors(i + 1).leg(Leg.MX).neighbour()).as("bond %d-%d", i, i + 1).hasValue(i);
      }
    }
  }

  private static double[] axis1(Leg leg) {
    return switch (leg) {
      case PX, MX -> new double[] {0, 1, 0};
      case PY, MY -> new double[] {0, 0, 1};
      case PZ, MZ -> new double[] {1, 0, 0};
    };
  }

  private static double[] axis2(Leg leg) {
    return switch (leg) {
      case PX, MX -> new double[] {0, 0, 1};
      case PY, MY -> new double[] {1, 0, 0};
      case PZ, MZ -> new double[] {0, 1, 0};
    };
  }

  private static double[] cross(double[] a, double[] b) {
    return new double[] {
      a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]
    };
  }

  private static double dot(double[] a, double[] b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }

  /** {@code v} rotated by the inverse of {@code q}: a world direction in the atom's frame. */
  private static double[] inverseRotate(Quat q, double x, double y, double z) {
    double w = q.w();
    double qx = -q.x();
    double qy = -q.y();
    double qz = -q.z();
    double tx = 2 * (qy * z - qz * y);
    double ty = 2 * (qz * x - qx * z);
    double tz = 2 * (qx * y - qy * x);
    return new double[] {
      x + w * tx + (qy * tz - qz * ty),
      y + w * ty + (qz * tx - qx * tz),
      z + w * tz + (qx * ty - qy * tx)
    };
  }
}

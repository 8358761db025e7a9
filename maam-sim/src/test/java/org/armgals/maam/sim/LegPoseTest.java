package org.armgals.maam.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.SplittableRandom;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.api.Test;
import org.ode4j.math.DVector3;

class LegPoseTest {

  private static final AtomParams P = AtomParams.defaults();

  @Test
  void theConeBoxHoldsTheCapsuleAtAnyAnglesInTheCone() {
    Cone cone = new Cone(P.coneHalfAngle());
    SplittableRandom random = new SplittableRandom(5);
    double[] out = new double[2];
    double[] box = new double[6];
    for (Leg leg : Leg.values()) {
      LegPose pose = new LegPose(leg, P.kernelRadius(), P.legLength());
      pose.coneBox(P.coneHalfAngle(), P.legRadius(), box);
      for (int trial = 0; trial < 2000; trial++) {
        double h = P.coneHalfAngle();
        // Half the trials on the cone's edge, where the capsule reaches farthest.
        double scale = trial % 2 == 0 ? 1 : random.nextDouble();
        cone.clamp(scale * random.nextDouble(-h, h) * 2, scale * random.nextDouble(-h, h) * 2, out);
        pose.pose(out[0], out[1]);
        DVector3 d = pose.direction();
        // Points of the capsule: within its radius of the segment between its caps' centres.
        for (int k = 0; k <= 20; k++) {
          double s = P.legRadius() + (P.legLength() - 2 * P.legRadius()) * k / 20;
          double[] u = randomUnit(random);
          for (int axis = 0; axis < 3; axis++) {
            double p = pose.pivot(axis) + s * d.get(axis) + P.legRadius() * u[axis];
            assertThat(p)
                .as("%s trial %d axis %d", leg, trial, axis)
                .isBetween(box[2 * axis], box[2 * axis + 1]);
          }
        }
      }
    }
  }

  private static double[] randomUnit(SplittableRandom random) {
    double[] u = {random.nextGaussian(), random.nextGaussian(), random.nextGaussian()};
    double n = Math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    return new double[] {u[0] / n, u[1] / n, u[2] / n};
  }

  @Test
  void thePoseIsThatOfTheAnglesLastWorkedOut() {
    LegPose reused = new LegPose(Leg.PX, P.kernelRadius(), P.legLength());
    reused.pose(0.2, -0.1);
    reused.pose(-0.3, 0.15);
    LegPose fresh = new LegPose(Leg.PX, P.kernelRadius(), P.legLength());
    fresh.pose(-0.3, 0.15);
    LegPose axisOnly = new LegPose(Leg.PX, P.kernelRadius(), P.legLength());
    axisOnly.turnAxis2(-0.3);
    for (int axis = 0; axis < 3; axis++) {
      assertThat(reused.tip().get(axis)).isEqualTo(fresh.tip().get(axis));
      assertThat(reused.centre().get(axis)).isEqualTo(fresh.centre().get(axis));
      assertThat(axisOnly.axis2().get(axis)).isEqualTo(fresh.axis2().get(axis));
    }
    // At rest the tip is the reach out along the leg's axis.
    reused.pose(0, 0);
    assertThat(reused.tip().get0()).isCloseTo(P.reach(), offset(1e-12));
  }
}

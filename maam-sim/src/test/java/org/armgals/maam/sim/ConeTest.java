package org.armgals.maam.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class ConeTest {

  private final double half = Math.toRadians(30);
  private final Cone cone = new Cone(half);

  @Test
  void aTargetInsideTheConeIsKept() {
    double[] out = new double[2];
    cone.clamp(0.1, -0.2, out);
    assertThat(out).containsExactly(0.1, -0.2);
  }

  @Test
  void aTargetOutsideTheConeIsBroughtOntoItsEdgeInTheSameDirection() {
    double[] out = new double[2];
    SplittableRandom random = new SplittableRandom(7);
    for (int i = 0; i < 1000; i++) {
      double a1 = random.nextDouble(-3, 3);
      double a2 = random.nextDouble(-3, 3);
      cone.clamp(a1, a2, out);
      assertThat(Cone.tilt(out[0], out[1])).isLessThanOrEqualTo(half + 1e-9);
      assertThat(Math.signum(out[0])).isIn(Math.signum(a1), 0.0);
      assertThat(Math.signum(out[1])).isIn(Math.signum(a2), 0.0);
    }
  }

  @Test
  void eachAxisStopFollowsTheOtherAxisSoThePairStaysOnTheCone() {
    assertThat(cone.stopGiven(0)).isCloseTo(half, offset(1e-12));
    double other = Math.toRadians(20);
    assertThat(Cone.tilt(cone.stopGiven(other), other)).isCloseTo(half, offset(1e-9));
    assertThat(cone.stopGiven(Math.toRadians(40))).isZero();
  }
}

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

  @Test
  void theFitIsTheBisectionsBitForBitAndSkipsMostOfItsCosines() {
    SplittableRandom random = new SplittableRandom(11);
    for (double h : new double[] {half, 0.01, 0.3, 1.0, 1.5}) {
      Cone c = new Cone(h);
      int outside = 0;
      int bounded = 0;
      for (int i = 0; i < 300_000; i++) {
        // Half the pairs near the edge's diagonal reach, where the edge is hardest to place.
        double a1 = c.limit(random.nextDouble(-1.2 * h, 1.2 * h));
        double a2 = c.limit(i % 2 == 0 ? random.nextDouble(-h, h) : Math.copySign(h, a1) * 0.8);
        double fit = c.fit(a1, a2);
        assertThat(Double.doubleToRawLongBits(fit))
            .as("h %s a1 %s a2 %s", h, a1, a2)
            .isEqualTo(Double.doubleToRawLongBits(c.fitBySearch(a1, a2)));
        if (fit != 1) {
          outside++;
          double f = c.edge(a1, a2);
          if (!Double.isNaN(c.surelyIn(a1, a2, f)) && !Double.isNaN(c.surelyOut(a1, a2, f))) {
            bounded++;
          }
        }
      }
      assertThat(outside).as("h %s", h).isGreaterThan(10_000);
      if (h >= 0.3) {
        assertThat(bounded).as("h %s", h).isEqualTo(outside);
      }
    }
  }
}

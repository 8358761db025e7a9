package org.armgals.maam.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class BoxesTest {

  private static boolean inside(double[] box, double x, double y, double z) {
    return box[0] <= x && x <= box[1] && box[2] <= y && y <= box[3] && box[4] <= z && z <= box[5];
  }

  @Test
  void aSegmentMissesABoxOnlyWhenNoPointOfItIsInside() {
    SplittableRandom random = new SplittableRandom(3);
    int misses = 0;
    int hits = 0;
    for (int trial = 0; trial < 20_000; trial++) {
      double[] box = new double[6];
      for (int axis = 0; axis < 3; axis++) {
        double a = random.nextDouble(-1, 1);
        double b = random.nextDouble(-1, 1);
        box[2 * axis] = Math.min(a, b);
        box[2 * axis + 1] = Math.max(a, b);
      }
      double[] aim = new double[6];
      double norm = 0;
      for (int axis = 0; axis < 3; axis++) {
        aim[axis] = random.nextDouble(-1.5, 1.5);
        // Some directions along an axis, as legs at rest point.
        aim[3 + axis] = trial % 7 == 0 && axis > 0 ? 0 : random.nextDouble(-1, 1);
        norm += aim[3 + axis] * aim[3 + axis];
      }
      for (int axis = 0; axis < 3; axis++) {
        aim[3 + axis] /= Math.sqrt(norm);
      }
      double length = random.nextDouble(0.1, 2);
      boolean pointInside = false;
      for (int k = 0; k <= 2000 && !pointInside; k++) {
        double t = length * k / 2000;
        pointInside = inside(box, aim[0] + t * aim[3], aim[1] + t * aim[4], aim[2] + t * aim[5]);
      }
      boolean missed = Boxes.segmentMisses(box, 0, aim, 0, length);
      if (pointInside) {
        assertThat(missed).as("trial %d", trial).isFalse();
        hits++;
      }
      if (missed) {
        misses++;
      }
    }
    assertThat(misses).isGreaterThan(300);
    assertThat(hits).isGreaterThan(300);
  }

  @Test
  void boxesThatTouchOverlapAsTheEnginesDo() {
    double[] a = {0, 1, 0, 1, 0, 1};
    double[] touching = {1, 2, 0, 1, 0, 1};
    double[] apart = {1.000001, 2, 0, 1, 0, 1};
    assertThat(Boxes.overlap(a, 0, touching, 0)).isTrue();
    assertThat(Boxes.overlap(a, 0, apart, 0)).isFalse();
  }
}

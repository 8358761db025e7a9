package org.armgals.maam.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.ode4j.math.DVector3;
import org.ode4j.ode.DContactGeomBuffer;
import org.ode4j.ode.DRay;
import org.ode4j.ode.OdeHelper;

/**
 * A ray meets the ground's plane, worked out without the engine (decision 0084), exactly where the
 * engine's ray-plane collider says it does, or misses it as the engine does.
 */
class GroundTest {

  private static final double RANGE = 0.3;

  @BeforeAll
  static void engine() {
    OdeHelper.initODE2(0);
  }

  @Test
  void aRayMeetsThePlaneWhereTheEngineSaysItDoes() {
    Ground ground = new Ground(List.of());
    DRay ray = OdeHelper.createRay(null, RANGE);
    DContactGeomBuffer contacts = new DContactGeomBuffer(1);
    SplittableRandom random = new SplittableRandom(17);
    double[] rays = new double[AtomModel.RAY];
    int hits = 0;
    int misses = 0;
    for (int i = 0; i < 20_000; i++) {
      DVector3 tip = new DVector3(random.nextDouble(-1, 1), random.nextDouble(-1, 1), z(random, i));
      DVector3 d = direction(random, i);
      aim(rays, tip, d);
      ray.set(tip, d);
      ray.setLength(RANGE);

      double expected =
          OdeHelper.collide(ray, ground.geoms.get(ground.plane), 1, contacts) > 0
              ? contacts.get(0).depth
              : Double.POSITIVE_INFINITY;

      assertThat(ground.rayOnPlane(rays, 0, RANGE))
          .as("ray %d from %s along %s", i, tip, d)
          .isEqualTo(expected);
      if (expected == Double.POSITIVE_INFINITY) {
        misses++;
      } else {
        hits++;
      }
    }
    // Both kinds were tried, with rays from above and below the plane, along it and across it.
    assertThat(hits).isGreaterThan(2_000);
    assertThat(misses).isGreaterThan(2_000);
    ray.destroy();
    ground.destroy();
  }

  /** Heights near the plane, some on it. */
  private static double z(SplittableRandom random, int i) {
    return i % 50 == 0 ? 0 : random.nextDouble(-0.4, 0.4);
  }

  /** Directions of any length, some along the plane and some straight down. */
  private static DVector3 direction(SplittableRandom random, int i) {
    double x = random.nextDouble(-1, 1);
    double y = random.nextDouble(-1, 1);
    return switch (i % 7) {
      case 0 -> new DVector3(x, y, 0);
      case 1 -> new DVector3(0, 0, -random.nextDouble(0.1, 3));
      default -> new DVector3(x, y, random.nextDouble(-1, 1)).scale(random.nextDouble(0.5, 2));
    };
  }

  /**
   * Writes a ray as {@link LegModel#placeRay} does: from, along, and along as the engine has it.
   */
  private static void aim(double[] rays, DVector3 tip, DVector3 d) {
    DVector3 unit = new DVector3(d).normalize();
    for (int axis = 0; axis < 3; axis++) {
      rays[axis] = tip.get(axis);
      rays[3 + axis] = d.get(axis);
      rays[AtomModel.RAY_UNIT + axis] = unit.get(axis);
    }
  }
}

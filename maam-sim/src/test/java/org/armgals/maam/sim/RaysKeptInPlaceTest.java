package org.armgals.maam.sim;

import static org.armgals.maam.sim.TestScenes.joints;
import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.api.Test;
import org.ode4j.math.DVector3;
import org.ode4j.ode.DRay;
import org.ode4j.ode.OdeHelper;

/**
 * A kinematic leg's ray is in place at the end of every cycle: placed in the last step's drain if
 * the leg or its kernel moved (decision 0084), left as it was if neither did (decision 0080).
 * Either way it is where aiming it afresh would put it: the numbers casting reads (where from,
 * along, the box and the unit direction, the last two worked out without the engine) and the
 * engine's ray are those of a ray aimed afresh, bit for bit.
 */
class RaysKeptInPlaceTest {

  @Test
  void everyRayIsWhereAimingItAfreshWouldPutIt() {
    // Nine atoms fall and settle; every other one swings a leg all the while.
    try (Simulation s =
        Simulation.builder(Scenes.grid(9, 0.4))
            .controllers(
                id ->
                    (body, cycle) -> {
                      if (id % 2 == 0) {
                        joints(body).setLegTarget(Leg.PX, 0.4 * Math.sin(cycle * 0.1), 0);
                      }
                    })
            .build()) {
      SimulationImpl sim = (SimulationImpl) s;
      DRay fresh = OdeHelper.createRay(null, s.scene().params().proximityRange());
      Map<Integer, double[]> before = new HashMap<>();
      int kept = 0;
      int placedAgain = 0;
      for (int c = 0; c < 150; c++) {
        for (int id : s.atomIds()) {
          before.put(id, sim.view(id).model.rays.clone());
        }
        s.runCycle();
        for (int id : s.atomIds()) {
          AtomModel atom = sim.view(id).model;
          for (LegModel leg : atom.legs) {
            if (leg.failed || leg.binding != null) {
              continue;
            }
            assertThat(leg.rayInPlace).as("atom %d leg %s, cycle %d", id, leg.leg, c).isTrue();
            int at = AtomModel.RAY * leg.leg.ordinal();
            double[] rays = Arrays.copyOfRange(atom.rays, at, at + AtomModel.RAY);
            if (Arrays.equals(rays, Arrays.copyOfRange(before.get(id), at, at + AtomModel.RAY))) {
              kept++;
            } else {
              placedAgain++;
            }
            DVector3 tip = leg.tip();
            DVector3 d = leg.direction();
            fresh.set(tip, d);
            double[] expected = new double[AtomModel.RAY];
            double[] from = {tip.get0(), tip.get1(), tip.get2(), d.get0(), d.get1(), d.get2()};
            System.arraycopy(from, 0, expected, 0, 6);
            Boxes.copy(fresh.getAABB(), expected, AtomModel.RAY_BOX);
            System.arraycopy(engineRay(fresh), 3, expected, AtomModel.RAY_UNIT, 3);
            assertThat(rays).as("atom %d leg %s, cycle %d", id, leg.leg, c).isEqualTo(expected);
            assertThat(engineRay(leg.engineRay())).isEqualTo(engineRay(fresh));
          }
        }
      }
      fresh.destroy();
      // Both kinds were seen: rays left in place, and rays of moving legs or atoms placed again.
      assertThat(kept).isGreaterThan(1000);
      assertThat(placedAgain).isGreaterThan(1000);
    }
  }

  /** Where the engine's ray starts and points, and how long it is. */
  private static double[] engineRay(DRay ray) {
    DVector3 start = new DVector3();
    DVector3 dir = new DVector3();
    ray.get(start, dir);
    return new double[] {
      start.get0(), start.get1(), start.get2(), dir.get0(), dir.get1(), dir.get2(), ray.getLength()
    };
  }
}

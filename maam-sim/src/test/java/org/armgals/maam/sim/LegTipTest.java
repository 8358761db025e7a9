package org.armgals.maam.sim;

import static org.armgals.maam.sim.TestScenes.atom;
import static org.armgals.maam.sim.TestScenes.joints;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.List;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.ode4j.math.DVector3;

/**
 * A reading's {@link AtomSensors#tip} is where the simulator has the leg's tip, on either leg
 * model: the geometry lives in the simulator once, and a picture drawn from readings (or from a
 * trace of them) draws the tips where they were.
 */
class LegTipTest {

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void theTipOfATurnedLegOfATurnedAtomIsWhereTheSimulatorHasIt(LegDynamics legs) {
    // weightless, so the atom stays where it is put: turned about a slanted axis, legs turned
    Scene scene =
        Scenes.parse(
            """
            scene tips
            gravity 0 0 0
            atom 1 0 0 0.2 1 2 0.5 35
            """);
    try (Simulation sim = Simulation.builder(scene).legDynamics(legs).build()) {
      AtomModel model = atom(sim, 1).model;
      List<AtomSensors> read = new ArrayList<>();
      List<DVector3> actual = new ArrayList<>();
      sim.setController(
          1,
          (body, cycle) -> {
            for (Leg leg : Leg.values()) {
              joints(body).setLegTarget(leg, -0.3, 0.2);
            }
            if (cycle == 39) { // the readings and the model at the same instant: the cycle's start
              read.add(joints(body).sensors());
              for (Leg leg : Leg.values()) {
                actual.add(model.leg(leg).tip());
              }
            }
          });
      sim.runCycles(40);
      double tolerance = legs == LegDynamics.KINEMATIC ? 1e-12 : 1e-3;

      for (Leg leg : Leg.values()) {
        assertThat(read.get(0).leg(leg).angles().elevation())
            .as("%s turned", leg)
            .isGreaterThan(0.2);
        Vec3 tip = read.get(0).tip(leg, scene.params());
        DVector3 at = actual.get(leg.ordinal());
        assertThat(tip.x()).as("%s's tip, x", leg).isCloseTo(at.get0(), within(tolerance));
        assertThat(tip.y()).as("%s's tip, y", leg).isCloseTo(at.get1(), within(tolerance));
        assertThat(tip.z()).as("%s's tip, z", leg).isCloseTo(at.get2(), within(tolerance));
      }
    }
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void straightLegsOfAnUprightAtomReachAlongTheAxes(LegDynamics legs) {
    Scene scene = Scenes.parse("scene upright\ngravity 0 0 0\natom 1 1 2 3\n");
    try (Simulation sim = Simulation.builder(scene).legDynamics(legs).build()) {
      AtomSensors read = sim.sensors(1);
      double reach = scene.params().reach();

      assertThat(read.tip(Leg.PX, scene.params())).isEqualTo(new Vec3(1 + reach, 2, 3));
      assertThat(read.tip(Leg.MZ, scene.params())).isEqualTo(new Vec3(1, 2, 3 - reach));
    }
  }
}

package org.armgals.examples.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import org.armgals.examples.plot.AtomView;
import org.armgals.maam.sim.AtomParams;
import org.armgals.maam.sim.AtomSensors;
import org.armgals.maam.sim.LegSensors;
import org.armgals.maam.sim.Quat;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.api.Test;

/**
 * The pictures put a leg's tip where the simulator has it: the simulator's proximity ray starts at
 * the tip and runs along the leg, so for every leg whose ray meets the ground, the tip drawn and
 * the direction from the leg's pivot to it predict the distance the ray measured.
 */
class ViewsTest {

  @Test
  void turnedLegsOfATurnedAtomHaveTheirTipsWhereTheSimulatorHasThem() {
    // weightless, so the atom stays where it is put: turned about a slanted axis, legs turned
    Scene scene =
        Scenes.parse(
            """
            scene views
            gravity 0 0 0
            atom 1 0 0 0.2 1 2 0.5 35
            """);
    AtomParams params = scene.params();
    try (Simulation sim = Simulation.builder(scene).build()) {
      sim.setController(
          1,
          (body, cycle) -> {
            for (Leg leg : Leg.values()) {
              body.setLegTarget(leg, -0.3, 0.2);
            }
          });
      sim.runCycles(40);
      AtomSensors atom = sim.atom(1).sensors();
      AtomView view = Views.of(atom, params);

      int hits = 0;
      for (int i = 0; i < 6; i++) {
        Leg leg = Leg.values()[i];
        LegSensors sensed = atom.leg(leg);
        assertThat(Math.abs(sensed.angle1())).as("%s turned", leg).isGreaterThan(0.2);
        AtomView.Vec tip = view.legs().get(i).tip();
        double[] pivot = pivot(atom, leg, params.kernelRadius());
        double[] d = {
          (tip.x() - pivot[0]) / params.legLength(),
          (tip.y() - pivot[1]) / params.legLength(),
          (tip.z() - pivot[2]) / params.legLength()
        };
        assertThat(Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]))
            .as("%s's length", leg)
            .isCloseTo(1, within(1e-9));
        double predicted = d[2] < 0 ? tip.z() / -d[2] : Double.POSITIVE_INFINITY;
        if (sensed.proximity() < params.proximityRange()) {
          hits++;
          assertThat(predicted)
              .as("%s's ray to the ground", leg)
              .isCloseTo(sensed.proximity(), within(0.003));
        } else {
          assertThat(predicted)
              .as("%s misses the ground", leg)
              .isGreaterThan(params.proximityRange() - 0.003);
        }
      }
      assertThat(hits).as("legs whose ray meets the ground").isPositive();
    }
  }

  /** Where the leg's joint is: on the kernel's surface, along the leg's rest axis. */
  private static double[] pivot(AtomSensors atom, Leg leg, double radius) {
    double[] axis = {leg.x(), leg.y(), leg.z()};
    Quat q = atom.orientation();
    double tx = 2 * (q.y() * axis[2] - q.z() * axis[1]);
    double ty = 2 * (q.z() * axis[0] - q.x() * axis[2]);
    double tz = 2 * (q.x() * axis[1] - q.y() * axis[0]);
    double[] turned = {
      axis[0] + q.w() * tx + (q.y() * tz - q.z() * ty),
      axis[1] + q.w() * ty + (q.z() * tx - q.x() * tz),
      axis[2] + q.w() * tz + (q.x() * ty - q.y() * tx)
    };
    return new double[] {
      atom.position().x() + radius * turned[0],
      atom.position().y() + radius * turned[1],
      atom.position().z() + radius * turned[2]
    };
  }

  @Test
  void straightLegsOfAnUprightAtomReachAlongTheAxes() {
    Scene scene = Scenes.parse("scene upright\ngravity 0 0 0\natom 1 1 2 3\n");
    try (Simulation sim = Simulation.builder(scene).build()) {
      AtomView view = Views.of(sim.atom(1).sensors(), scene.params());
      double reach = scene.params().reach();
      List<AtomView.Leg> legs = view.legs();
      assertThat(legs.get(Leg.PX.ordinal()).tip()).isEqualTo(new AtomView.Vec(1 + reach, 2, 3));
      assertThat(legs.get(Leg.MZ.ordinal()).tip()).isEqualTo(new AtomView.Vec(1, 2, 3 - reach));
    }
  }
}

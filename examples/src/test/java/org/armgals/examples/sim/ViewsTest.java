package org.armgals.examples.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.armgals.examples.plot.AtomView;
import org.armgals.maam.sim.AtomParams;
import org.armgals.maam.sim.AtomSensors;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.sim.Vec3;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;
import org.junit.jupiter.api.Test;

/**
 * The pictures draw an atom as its readings place it: each leg's tip where the simulator has it
 * ({@link AtomSensors#tip}, held to the simulator by maam-sim's {@code LegTipTest}), bound or not.
 */
class ViewsTest {

  @Test
  void turnedLegsOfATurnedAtomAreDrawnToTheTipsTheReadingsPlace() {
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
              body.command(Atom.target(leg), new LegAngles(0.36, 0.97));
            }
          });
      sim.runCycles(40);
      AtomSensors atom = sim.sensors(1);

      AtomView view = Views.of(atom, params);

      assertThat(view.centre())
          .isEqualTo(
              new AtomView.Vec(atom.position().x(), atom.position().y(), atom.position().z()));
      for (Leg leg : Leg.values()) {
        Vec3 tip = atom.tip(leg, params);
        assertThat(view.legs().get(leg.ordinal()).tip())
            .as("%s's tip", leg)
            .isEqualTo(new AtomView.Vec(tip.x(), tip.y(), tip.z()));
        assertThat(view.legs().get(leg.ordinal()).bound()).as("%s bound", leg).isFalse();
      }
    }
  }

  @Test
  void straightLegsOfAnUprightAtomReachAlongTheAxes() {
    Scene scene = Scenes.parse("scene upright\ngravity 0 0 0\natom 1 1 2 3\n");
    try (Simulation sim = Simulation.builder(scene).build()) {
      AtomView view = Views.of(sim.sensors(1), scene.params());
      double reach = scene.params().reach();
      List<AtomView.Leg> legs = view.legs();
      assertThat(legs.get(Leg.PX.ordinal()).tip()).isEqualTo(new AtomView.Vec(1 + reach, 2, 3));
      assertThat(legs.get(Leg.MZ.ordinal()).tip()).isEqualTo(new AtomView.Vec(1, 2, 3 - reach));
    }
  }
}

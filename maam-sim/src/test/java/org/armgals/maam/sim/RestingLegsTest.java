package org.armgals.maam.sim;

import static org.armgals.maam.sim.TestScenes.joints;
import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.api.Test;

/**
 * A kinematic leg whose servo rests is skipped until something it reads changes (decision 0080):
 * the run is the same, bit for bit, as when every servo works out every step, on atoms that settle
 * side by side, turn a leg now and then (into their neighbours), go limp, have their torque
 * limited, are pushed (one off the ground), lose a leg or fail, and run their batteries flat.
 */
class RestingLegsTest {

  private static final int CYCLES = 250;

  /** Every atom's sensors after each cycle, and how many of its legs rested then. */
  private record Run(List<AtomSensors> sensed, int resting) {}

  private static Run run(boolean mayRest) {
    AtomParams p = AtomParams.defaults();
    Scene grid = Scenes.grid(9, 0.21);
    // A battery that runs flat within the run.
    Scene scene =
        Scenes.parse(
            "scene resting\nparam batteryCapacity " + p.idleDraw() * 1.5 + "\natom 1 0 0 1\n");
    scene =
        new Scene("resting", scene.params(), grid.gravity(), List.of(), grid.atoms(), List.of());
    try (Simulation s =
        Simulation.builder(scene).controllers(RestingLegsTest::controller).build()) {
      SimulationImpl sim = (SimulationImpl) s;
      if (!mayRest) {
        sim.neverRest();
      }
      List<AtomSensors> sensed = new ArrayList<>();
      int resting = 0;
      for (int c = 0; c < CYCLES; c++) {
        switch (c) {
          case 80 -> s.push(5, new Vec3(3, 0, 0));
          case 90 -> s.push(2, new Vec3(0, 0, 40));
          case 100 -> s.failLeg(4, Leg.MX);
          case 120 -> s.failAtom(7);
          default -> {}
        }
        s.runCycle();
        for (int id : s.atomIds()) {
          sensed.add(s.sensors(id));
          resting += Integer.bitCount(sim.view(id).model.resting);
        }
      }
      return new Run(sensed, resting);
    }
  }

  /** Atom {@code id}'s controller: a new target now and then, a limp leg, a weaker one. */
  private static org.armgals.maam.sim.spi.Controller controller(int id) {
    SplittableRandom random = new SplittableRandom(id);
    return (body, cycle) -> {
      if (id % 3 == 0 && cycle % 30 == 0) {
        joints(body).setLegTarget(Leg.PX, random.nextDouble(-0.5, 0.5), 0.1);
      }
      if (id % 3 == 1 && cycle == 40) {
        joints(body).relax(Leg.PY);
      }
      if (id % 3 == 1 && cycle == 60) {
        joints(body).setTorqueLimit(Leg.MZ, 0.001);
      }
      if (id % 3 == 2 && cycle == 70) {
        joints(body).setLegTarget(Leg.MX, 0.2, -0.1);
      }
    };
  }

  @Test
  void restingLegsRunBitForBitAsLegsWhoseServosWorkEveryStep() {
    Run resting = run(true);
    Run working = run(false);
    // Records compare their doubles bit for bit (but NaN).
    assertThat(resting.sensed()).isEqualTo(working.sensed());
    // Legs did rest (and with none resting, none is counted); the batteries ran flat.
    assertThat(resting.resting()).isGreaterThan(CYCLES * 9);
    assertThat(working.resting()).isZero();
    assertThat(resting.sensed().getLast().energy()).isZero();
  }
}

package org.armgals.maam.guide;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.api.Test;

/** The framework guide's balancing atom, run unchanged on a simulated atom in virtual time. */
class BalancingAtomOnTheSimulatorTest {

  @Test
  void theGuidesRobotDrivesASimulatedAtomsLegsToItsStance() {
    try (Simulation sim =
        Simulation.builder(Scenes.parse("scene float\ngravity 0 0 0\natom 1 0 0 1")).build()) {
      Body body = sim.body(1);
      BalancingAtom robot = new BalancingAtom(body, sim::timeNanos);
      sim.setController(1, (atom, cycle) -> robot.cycle());
      double full = body.read(Atom.BATTERY);
      sim.runCycles(40);
      assertThat(robot.cycles()).isEqualTo(40);
      assertThat(robot.errors()).isZero();
      // Level, so no stimulus: Balance asks for the narrow stance, elevation 0.2 rad, on every leg.
      for (Leg leg : Leg.values()) {
        assertThat(body.read(Atom.angles(leg)).elevation())
            .as("%s", leg)
            .isCloseTo(0.2, offset(0.01));
      }
      assertThat(body.read(Atom.BATTERY)).isLessThan(full);
    }
  }
}

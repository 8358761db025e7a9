package org.armgals.maam.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.time.Duration;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.api.Test;

/** A jointed leg's torque sensors read the torque its motors hold it with. */
class LegTorqueTest {

  @Test
  void anUpperLegOfATripodAtRestReadsTheTorqueThatHoldsItsWeight() {
    try (Simulation s =
        Simulation.builder(Scenes.builtIn("single")).legDynamics(LegDynamics.JOINTED).build()) {
      s.runFor(Duration.ofSeconds(1));
      AtomParams p = s.scene().params();
      // Resting as a tripod, the (1, 1, 1) diagonal points up: each upper leg leans
      // acos(1/sqrt 3) from the vertical, its weight pulling at half its length from the pivot.
      // The engine's iterative solver reports joint forces to within some 20 %; read before the
      // fix, the kernel's side of the joint, they were 3.5 times too large.
      double lean = Math.acos(1 / Math.sqrt(3));
      double expected = p.legMass() * 9.81 * p.legLength() / 2 * Math.sin(lean);
      for (Leg leg : new Leg[] {Leg.PX, Leg.PY, Leg.PZ}) {
        LegSensors sensed = s.sensors(1).leg(leg);
        assertThat(Math.hypot(sensed.torque1(), sensed.torque2()))
            .as("torque holding %s", leg)
            .isCloseTo(expected, within(0.25 * expected));
      }
    }
  }
}

package org.armgals.maam.sim;

import static org.armgals.maam.sim.TestScenes.atom;
import static org.armgals.maam.sim.TestScenes.joints;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.time.Duration;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

class EnergyTest {

  private static final String FREE = "scene free\ngravity 0 0 0\n";

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void withLimpLegsTheBatteryDrainsByTheIdleDrawAlone(LegDynamics dynamics) {
    AtomParams p = AtomParams.defaults();
    try (Simulation s =
        Simulation.builder(Scenes.parse(FREE + "atom 1 0 0 1")).legDynamics(dynamics).build()) {
      for (Leg leg : Leg.values()) {
        atom(s, 1).relax(leg);
      }
      s.runFor(Duration.ofSeconds(1));
      s.runCycle();
      double seconds = 1.0;
      assertThat(s.sensors(1).energy())
          .isCloseTo(p.batteryCapacity() - p.idleDraw() * seconds, offset(1e-9));
    }
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void movingLegsCostTheirMechanicalWorkOverTheEfficiencyOnTopOfTheIdleDraw(LegDynamics dynamics) {
    AtomParams p = AtomParams.defaults();
    double[] work = {0};
    try (Simulation s =
        Simulation.builder(Scenes.parse(FREE + "atom 1 0 0 1"))
            .legDynamics(dynamics)
            .controller(
                1,
                (body, cycle) -> {
                  double a = (cycle / 20) % 2 == 0 ? 0.4 : -0.4;
                  for (Leg leg : Leg.values()) {
                    joints(body).setLegTarget(leg, a, -a);
                  }
                })
            .build()) {
      s.runFor(Duration.ofSeconds(1));
      s.runCycle();
      double spent = p.batteryCapacity() - s.sensors(1).energy();
      work[0] = spent - p.idleDraw() * 1.0;
    }
    // Six legs swinging 0.8 rad against their own inertia: some work, and not an absurd amount.
    assertThat(work[0]).isGreaterThan(1e-4).isLessThan(6 * 2 * p.maxTorque() * p.maxSpeed());
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void anEmptyBatteryStopsTheMotors(LegDynamics dynamics) {
    // 0.05 J at a 0.1 W idle draw: empty after half a second.
    try (Simulation s =
        Simulation.builder(Scenes.parse(FREE + "param batteryCapacity 0.05\natom 1 0 0 1"))
            .legDynamics(dynamics)
            .build()) {
      s.runFor(Duration.ofMillis(600));
      assertThat(s.sensors(1).energy()).isZero();
      atom(s, 1).setLegTarget(Leg.PZ, 0.4, 0);
      s.runFor(Duration.ofMillis(300));
      assertThat(s.sensors(1).leg(Leg.PZ).angles().elevation()).isCloseTo(0, offset(0.01));
    }
    try (Simulation s =
        Simulation.builder(Scenes.parse(FREE + "param batteryCapacity 0.05\natom 1 0 0 1"))
            .legDynamics(dynamics)
            .build()) {
      boolean reported = false;
      for (int i = 0; i < 60; i++) {
        s.runCycle();
        reported |= s.lastEvents().contains(new SimEvent.BatteryEmpty(500_000_000, 1));
      }
      assertThat(reported).isTrue();
    }
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void aChargedBatteryDrivesTheSameLegToItsTarget(LegDynamics dynamics) {
    try (Simulation s =
        Simulation.builder(Scenes.parse(FREE + "atom 1 0 0 1")).legDynamics(dynamics).build()) {
      atom(s, 1).setLegTarget(Leg.PZ, 0.4, 0);
      s.runFor(Duration.ofMillis(300));
      s.runCycle();
      assertThat(s.sensors(1).leg(Leg.PZ).angles().elevation()).isCloseTo(0.4, offset(0.01));
    }
  }
}

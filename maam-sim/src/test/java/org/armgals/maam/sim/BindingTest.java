package org.armgals.maam.sim;

import static org.armgals.maam.sim.TestScenes.atom;
import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

class BindingTest {

  private static List<SimEvent> runLocked(LegDynamics dynamics, Scene scene, int cycles) {
    List<SimEvent> events = new ArrayList<>();
    try (Simulation s = Simulation.builder(scene).legDynamics(dynamics).build()) {
      atom(s, 1).bind(Leg.PX);
      atom(s, 2).bind(Leg.MX);
      for (int i = 0; i < cycles; i++) {
        s.runCycle();
        events.addAll(s.lastEvents());
      }
    }
    return events;
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void tipsWithinDistanceAndAlignmentBind(LegDynamics dynamics) {
    assertThat(runLocked(dynamics, TestScenes.facing(0.003, 0, ""), 3))
        .containsExactly(new SimEvent.Bound(0, 1, Leg.PX, 2, Leg.MX));
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void tipsTooFarApartDoNotBind(LegDynamics dynamics) {
    assertThat(runLocked(dynamics, TestScenes.facing(0.02, 0, ""), 20)).isEmpty();
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void misalignedTipsDoNotBind(LegDynamics dynamics) {
    // Atom 2 turned 25 degrees about z: its -x leg is 25 degrees off the reverse of 1's +x leg.
    Scene scene = TestScenes.facing(-0.002, 25, "");
    assertThat(runLocked(dynamics, scene, 20)).isEmpty();
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void onlyLockedTipsBindUnlessAutoLockIsOn(LegDynamics dynamics) {
    try (Simulation s =
        Simulation.builder(TestScenes.facing(0.003, 0, "")).legDynamics(dynamics).build()) {
      atom(s, 1).bind(Leg.PX);
      s.runCycles(5);
      assertThat(s.sensors(1).leg(Leg.PX).neighbour()).isEmpty();
    }
    try (Simulation s =
        Simulation.builder(TestScenes.facing(0.003, 0, "param autoLock true\n"))
            .legDynamics(dynamics)
            .build()) {
      s.runCycles(2);
      assertThat(s.sensors(1).leg(Leg.PX).neighbour()).hasValue(2);
    }
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void aBindingHoldsBelowItsStrengthAndBreaksAboveIt(LegDynamics dynamics) {
    double strength = AtomParams.defaults().bindStrength();
    try (Simulation s =
        Simulation.builder(TestScenes.boundPair("")).legDynamics(dynamics).build()) {
      for (int i = 0; i < 30; i++) {
        s.push(1, new Vec3(-0.5 * strength, 0, 0));
        s.push(2, new Vec3(0.5 * strength, 0, 0));
        s.runCycle();
        assertThat(s.lastEvents()).isEmpty();
      }
      s.push(1, new Vec3(-2 * strength, 0, 0));
      s.push(2, new Vec3(2 * strength, 0, 0));
      s.runCycle();
      assertThat(s.lastEvents())
          .singleElement()
          .isInstanceOfSatisfying(
              SimEvent.BindingBroke.class,
              broke -> {
                assertThat(broke.force()).isGreaterThan(strength);
                assertThat(broke.atomA()).isEqualTo(1);
                assertThat(broke.legB()).isEqualTo(Leg.MX);
              });
      s.runCycle();
      assertThat(s.sensors(1).leg(Leg.PX).neighbour()).isEmpty();
      assertThat(s.sensors(1).leg(Leg.PX).locked()).isFalse();
    }
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void unbindReleasesTheBindingOnCommand(LegDynamics dynamics) {
    try (Simulation s =
        Simulation.builder(TestScenes.boundPair("")).legDynamics(dynamics).build()) {
      s.runCycle();
      atom(s, 2).unbind(Leg.MX);
      s.runCycle();
      assertThat(s.lastEvents())
          .containsExactly(new SimEvent.Unbound(10_000_000, 2, Leg.MX, 1, Leg.PX));
      s.runCycle();
      assertThat(s.sensors(1).leg(Leg.PX).neighbour()).isEmpty();
    }
  }
}

package org.armgals.maam.sim;

import static org.armgals.maam.sim.TestScenes.atom;
import static org.armgals.maam.sim.TestScenes.joints;
import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.SplittableRandom;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

class PhysicsSanityTest {

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void anAtomAtRestStaysAtRest(LegDynamics dynamics) {
    try (Simulation s =
        Simulation.builder(Scenes.builtIn("single")).legDynamics(dynamics).build()) {
      s.runFor(Duration.ofMillis(500));
      AtomSensors settled = s.sensors(1);
      s.runFor(Duration.ofSeconds(2));
      AtomSensors later = s.sensors(1);
      assertThat(TestScenes.distance(settled.position(), later.position())).isLessThan(0.002);
      assertThat(Math.abs(later.tilt() - settled.tilt())).isLessThan(0.01);
      assertThat(later.position().z()).isBetween(0.05, 0.08);
      for (Leg leg : new Leg[] {Leg.MX, Leg.MY, Leg.MZ}) {
        assertThat(later.leg(leg).tipContact()).as("tip %s on the ground", leg).isTrue();
      }
      assertThat(later.leg(Leg.PZ).tipContact()).isFalse();
    }
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void anAtomWavingItsUpperLegsStaysWhereItStandsWithItsLowerTipsOnTheGround(LegDynamics dynamics) {
    try (Simulation s =
        Simulation.builder(Scenes.builtIn("single"))
            .legDynamics(dynamics)
            .controller(
                1,
                (body, cycle) -> {
                  double a = 0.4 * Math.sin(cycle * 0.05);
                  joints(body).setLegTarget(Leg.PX, a, 0);
                  joints(body).setLegTarget(Leg.PY, 0, a);
                  joints(body).setLegTarget(Leg.PZ, a, -a);
                })
            .build()) {
      s.runFor(Duration.ofMillis(500));
      Vec3 settled = s.sensors(1).position();
      for (int cycle = 0; cycle < 200; cycle++) {
        s.runCycle();
        AtomSensors sensors = s.sensors(1);
        for (Leg leg : new Leg[] {Leg.MX, Leg.MY, Leg.MZ}) {
          assertThat(sensors.leg(leg).tipContact()).as("tip %s on the ground", leg).isTrue();
        }
        for (Leg leg : new Leg[] {Leg.PX, Leg.PY, Leg.PZ}) {
          assertThat(sensors.leg(leg).tipContact()).as("tip %s in the air", leg).isFalse();
        }
      }
      assertThat(TestScenes.distance(settled, s.sensors(1).position())).isLessThan(0.002);
      if (dynamics == LegDynamics.KINEMATIC) {
        assertThat(atom(s, 1).model.kernel.isEnabled()).as("at rest").isFalse();
      }
    }
  }

  @Test
  void aKinematicLegThatReachesItsTargetStopsThereAndItsAtomRests() {
    try (Simulation s =
        Simulation.builder(Scenes.builtIn("single"))
            .legDynamics(LegDynamics.KINEMATIC)
            .controller(1, (body, cycle) -> joints(body).setLegTarget(Leg.MZ, 0.05, -0.02))
            .build()) {
      s.runFor(Duration.ofSeconds(3));
      LegSensors leg = s.sensors(1).leg(Leg.MZ);
      assertThat(leg.angles()).isEqualTo(JointAngles.legAngles(0.05, -0.02));
      // A leg still creeping towards its target where it touches the ground would keep it awake.
      assertThat(atom(s, 1).model.kernel.isEnabled()).isFalse();
    }
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void aLegNeverLeavesItsCone(LegDynamics dynamics) {
    double half = AtomParams.defaults().coneHalfAngle();
    SplittableRandom random = new SplittableRandom(3);
    try (Simulation s =
        Simulation.builder(Scenes.builtIn("chain4"))
            .legDynamics(dynamics)
            .controllers(
                id ->
                    (body, cycle) -> {
                      for (Leg leg : Leg.values()) {
                        joints(body)
                            .setLegTarget(leg, random.nextDouble(-2, 2), random.nextDouble(-2, 2));
                      }
                    })
            .build()) {
      for (int i = 0; i < 150; i++) {
        if (i % 10 == 0) {
          s.push(1 + i % 4, new Vec3(random.nextDouble(-20, 20), random.nextDouble(-20, 20), 5));
        }
        s.runCycle();
        for (int id : s.atomIds()) {
          for (LegSensors leg : s.sensors(id).legs()) {
            assertThat(leg.angles().elevation())
                .as("cycle %d atom %d leg %s", i, id, leg.leg())
                .isLessThanOrEqualTo(half + 0.02);
          }
        }
      }
    }
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void aBoundPairMovesAsOne(LegDynamics dynamics) {
    try (Simulation s =
        Simulation.builder(TestScenes.boundPair("")).legDynamics(dynamics).build()) {
      Vec3 start2 = s.sensors(2).position();
      double apart = TestScenes.distance(start2, s.sensors(1).position());
      for (int i = 0; i < 100; i++) {
        s.push(1, new Vec3(0, 3, 1));
        s.runCycle();
        AtomSensors a = s.sensors(1);
        AtomSensors b = s.sensors(2);
        assertThat(TestScenes.distance(a.position(), b.position())).isCloseTo(apart, within(0.002));
        double dot =
            a.orientation().w() * b.orientation().w()
                + a.orientation().x() * b.orientation().x()
                + a.orientation().y() * b.orientation().y()
                + a.orientation().z() * b.orientation().z();
        assertThat(Math.abs(dot)).isGreaterThan(Math.cos(Math.toRadians(2) / 2));
      }
      assertThat(TestScenes.distance(s.sensors(2).position(), start2)).isGreaterThan(0.05);
      assertThat(s.sensors(1).leg(Leg.PX).neighbour()).hasValue(2);
      assertThat(s.sensors(2).leg(Leg.MX).neighbour()).hasValue(1);
    }
  }

  private static org.assertj.core.data.Offset<Double> within(double d) {
    return org.assertj.core.data.Offset.offset(d);
  }
}

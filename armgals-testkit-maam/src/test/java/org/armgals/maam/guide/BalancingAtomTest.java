package org.armgals.maam.guide;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import org.armgals.active.ActiveRuntime;
import org.armgals.gals.Island;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.StructuralMeta;
import org.armgals.maam.RobotKind;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;
import org.armgals.maam.spi.Tilt;
import org.armgals.representation.p.PState;
import org.armgals.testkit.maam.FakeBody;
import org.junit.jupiter.api.Test;

/** The guide's robot, a kernel entity on an island stepped by hand, with a fake atom. */
class BalancingAtomTest {

  @Test
  void balancingAtomOpensItsLegsWhenTiltedAndRestsWhenItsBatteryIsLow() {
    FakeBody body = FakeBody.atom("atom-1", 100.0);
    // tag::run[]
    try (ActiveRuntime runtime = ActiveRuntime.create();
        Kernel kernel = StructuralMeta.bootstrap(runtime);
        Island island = Island.builder("atoms", runtime).period(Duration.ofMillis(10)).build()) {
      // virtual time: the island's instant times its period
      BalancingAtom robot = new BalancingAtom(body, () -> island.instant() * 10_000_000L);
      // the robot is a kernel entity of its kind, here with the kernel's basic behavioral meta
      StructuralMeta<PState> kind = RobotKind.define(kernel, "BalancingAtom", robot.observation());
      robot.start(island, kind, kernel.basicBehavioralMeta(), island.entityOptions());
      island.step(3); // three cycles, level
      // end::run[]
      assertThat(body.cycles()).isEqualTo(3);
      assertThat(robot.schedule().names())
          .containsExactly("tilt", "battery", "rest", "balance", "legs");
      assertThat(body.lastCommand(Atom.target(Leg.PZ))).contains(new LegAngles(0.2, 0));

      body.set(Atom.TILT, new Tilt(0.25, 0));
      island.step();
      assertThat(body.lastCommand(Atom.target(Leg.MX))).contains(new LegAngles(0.7, 0));

      body.set(Atom.BATTERY, 5.0);
      island.step();
      assertThat(body.lastCommand(Atom.target(Leg.MX))).contains(new LegAngles(0, 0));

      body.set(Atom.BATTERY, 50.0);
      island.step(5); // 10..50 ms after the last low reading: still resting
      assertThat(body.lastCommand(Atom.target(Leg.MX))).contains(new LegAngles(0, 0));
      island.step();
      assertThat(body.lastCommand(Atom.target(Leg.MX))).contains(new LegAngles(0.7, 0));
      assertThat(robot.cycles()).isEqualTo(11);
      assertThat(robot.errors()).isZero();
    }
  }
}

package org.armgals.maam.guide;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.armgals.active.ActiveRuntime;
import org.armgals.gals.Island;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.KernelOptions;
import org.armgals.kernel.ModelView;
import org.armgals.kernel.NotificationPolicy;
import org.armgals.kernel.StructuralMeta;
import org.armgals.maam.RobotKind;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;
import org.armgals.maam.spi.Tilt;
import org.armgals.representation.p.PState;
import org.armgals.testkit.maam.FakeBody;
import org.junit.jupiter.api.Test;

/**
 * The guide's robot, a kernel entity on an island stepped by hand, with a fake atom: with the
 * kernel's basic meta, then with its own meta level in lock step.
 */
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

  @Test
  void itsMetaLevelStrengthensTheBalanceOneCycleAfterTheAtomLeansAndNoOftenerThanItsDampingLets() {
    FakeBody body = FakeBody.atom("atom-1", 100.0);
    List<Double> stances = new ArrayList<>();
    // tag::meta-run[]
    long period = Duration.ofMillis(10).toNanos();
    try (ActiveRuntime runtime = ActiveRuntime.create();
        Island island = Island.builder("atoms", runtime).period(Duration.ofMillis(10)).build();
        // the kernel stamps notifications with the island's virtual time: damping counts in it
        Kernel kernel =
            StructuralMeta.bootstrap(
                runtime,
                KernelOptions.defaults().withTimeSource(() -> island.instant() * period))) {
      BalancingAtom robot = new BalancingAtom(body, () -> island.instant() * period);
      SteadyMeta meta = new SteadyMeta();
      meta.start(kernel); // a behavioral meta-entity of the kernel, on its own object
      robot.start(
          island,
          BalancingKind.define(kernel),
          meta,
          island
              .entityOptions()
              .withNotification(NotificationPolicy.statesOnly()) // a state event every cycle
              .withLockStep(1, Duration.ofSeconds(10))); // decided on cycle n, applied at n + 1
      meta.setFilter(robot, SteadyMeta.LEANING).touch();
      island.step(3); // level: nothing passes the filter
      body.set(Atom.TILT, new Tilt(0.25, 0)); // from cycle 4 on, it leans
      for (int cycle = 4; cycle <= 20; cycle++) {
        island.step();
        stances.add(body.lastCommand(Atom.target(Leg.MX)).orElseThrow().elevation());
      }
      ModelView model = meta.model(robot).getValue(); // the meta's model of the robot
      // end::meta-run[]
      // Cycle 4 runs gain 2 (0.7 rad); the request decided on it applies from cycle 5 (gain 3:
      // 0.95 rad); the damping holds back those of cycles 5 to 13, less than 100 ms after cycle 4;
      // the one decided on cycle 14 applies from cycle 15 (gain 4: 1.2 rad, the most); those of
      // cycles 15 to 20 are held back again.
      List<Double> expected = new ArrayList<>();
      for (int cycle = 4; cycle <= 20; cycle++) {
        expected.add(cycle == 4 ? 0.7 : cycle < 15 ? 0.95 : 1.2);
      }
      assertThat(stances)
          .usingElementComparator((a, b) -> Math.abs(a - b) < 1e-9 ? 0 : Double.compare(a, b))
          .isEqualTo(expected);
      assertThat(model.appliedVersion()).isEqualTo(2);
      assertThat(model.suppressedAdaptations()).isEqualTo(15);
      assertThat(model.refusedAdaptations()).isZero();
      assertThat(java.util.Objects.requireNonNull(model.state()).observe())
          .containsEntry(BalancingAtom.LEAN, 0.25);
      assertThat(robot.errors()).isZero();
    }
  }
}

package org.armgals.maam.spi;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.armgals.maam.sim.LegDynamics;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.sim.spi.Controller;
import org.junit.jupiter.api.Test;

/** The framework's body SPI contract, held against the simulator's atoms (jointed legs). */
class SimBodyContractTest extends BodyContract {

  /** The leg model the atoms are built with. */
  LegDynamics dynamics() {
    return LegDynamics.JOINTED;
  }

  @Override
  Body atom(String id) {
    if (!id.matches("a\\d+")) {
      throw new IllegalArgumentException("simulated atom ids are a<number>, not '" + id + "'");
    }
    Simulation s =
        Simulation.builder(Scenes.parse("atom " + id.substring(1) + " 0 0 0.07 tripod"))
            .legDynamics(dynamics())
            .build();
    s.runCycle();
    return s.body(Integer.parseInt(id.substring(1)));
  }

  @Test
  void eachControllerIsHandedTheBodyTheSimulationGivesForItsAtom() {
    List<String> handed = new ArrayList<>();
    List<Body> bodies = new ArrayList<>();
    try (Simulation s =
        Simulation.builder(Scenes.parse("gravity 0 0 0\natom 1 0 0 1\natom 2 1 0 1"))
            .legDynamics(dynamics())
            .controllers(
                id ->
                    (body, cycle) -> {
                      handed.add(id + ":" + body.id() + "@" + cycle);
                      bodies.add(body);
                    })
            .build()) {
      s.runCycles(2);
      assertThat(handed).containsExactly("1:a1@0", "2:a2@0", "1:a1@1", "2:a2@1");
      assertThat(bodies.get(0)).isSameAs(s.body(1)).isSameAs(bodies.get(2));
      assertThat(bodies.get(1)).isSameAs(s.body(2)).isSameAs(bodies.get(3));
    }
  }

  @Test
  void aDrivingControllerStepsItsRobotAndRefusesAnotherAtomsBody() {
    try (Simulation s =
        Simulation.builder(Scenes.parse("gravity 0 0 0\natom 1 0 0 1\natom 2 1 0 1"))
            .legDynamics(dynamics())
            .build()) {
      AtomicInteger steps = new AtomicInteger();
      s.setController(1, Controller.driving(s.body(1), steps::incrementAndGet));
      s.runCycles(3);
      assertThat(steps).hasValue(3);
      s.setController(2, Controller.driving(s.body(1), steps::incrementAndGet));
      assertThatThrownBy(s::runCycle)
          .isInstanceOf(IllegalStateException.class)
          .hasMessageContaining("handed body a2")
          .hasMessageContaining("built on body a1");
    }
  }

  @Test
  void aTargetCommandedThroughTheSpiIsReadBackAfterTheLegMoves() {
    Simulation s =
        Simulation.builder(Scenes.parse("gravity 0 0 0\natom 1 0 0 1"))
            .legDynamics(dynamics())
            .build();
    Body body = s.body(1);
    LegAngles target = new LegAngles(0.3, 1.0);
    body.command(Atom.target(Leg.PZ), target);
    s.runCycles(50);
    LegAngles read = body.read(Atom.angles(Leg.PZ));
    assertThat(read.elevation()).isCloseTo(0.3, org.assertj.core.data.Offset.offset(0.01));
    assertThat(read.azimuth()).isCloseTo(1.0, org.assertj.core.data.Offset.offset(0.03));
    assertThat(body.read(Atom.proximity(Leg.PZ))).isInfinite();
    assertThat(body.read(Atom.TILT).roll()).isCloseTo(0, org.assertj.core.data.Offset.offset(0.05));
    s.close();
  }

  @Test
  void boundNeighboursSeeEachOtherAndExchangeMessagesThroughTheSpi() {
    Simulation s =
        Simulation.builder(
                Scenes.parse("gravity 0 0 0\natom 1 0 0 1\natom 2 0.22 0 1\nbond 1:+x 2:-x"))
            .legDynamics(dynamics())
            .build();
    s.runCycle();
    Body one = s.body(1);
    Body two = s.body(2);
    assertThat(one.read(Atom.binding(Leg.PX))).isEqualTo(new LegBinding.Bound("a2", Leg.MX));
    one.command(Atom.SEND, new NeighbourMessage(Leg.PX, "hello"));
    s.runCycle();
    assertThat(two.read(Atom.INBOX).messages())
        .containsExactly(new NeighbourMessage(Leg.MX, "hello"));
    two.command(Atom.bind(Leg.MX), BindCommand.UNBIND);
    s.runCycle();
    assertThat(one.read(Atom.binding(Leg.PX))).isEqualTo(LegBinding.FREE);
    s.close();
  }
}

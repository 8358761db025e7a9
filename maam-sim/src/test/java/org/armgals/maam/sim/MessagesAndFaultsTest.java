package org.armgals.maam.sim;

import static org.armgals.maam.sim.TestScenes.atom;
import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.api.Test;

class MessagesAndFaultsTest {

  @Test
  void aMessageThroughABoundLegArrivesAfterTheDelay() {
    try (Simulation s =
        Simulation.builder(TestScenes.boundPair("")).messageDelay(Duration.ofMillis(30)).build()) {
      assertThat(atom(s, 1).send(Leg.PX, "hi")).isTrue();
      List<Long> arrivals = new ArrayList<>();
      for (int i = 0; i < 6; i++) {
        s.runCycle();
        if (!atom(s, 2).receive().isEmpty()) {
          arrivals.add(s.timeNanos());
          assertThat(atom(s, 2).receive())
              .containsExactly(new ReceivedMessage(1, Leg.PX, Leg.MX, 0, "hi"));
        }
      }
      // Sent at 0, due at 30 ms: received by the cycle starting at 30 ms (which ends at 40).
      assertThat(arrivals).containsExactly(40_000_000L);
    }
  }

  @Test
  void aLegThatIsNotBoundSendsNothing() {
    try (Simulation s = Simulation.builder(TestScenes.boundPair("")).build()) {
      assertThat(atom(s, 1).send(Leg.PY, "hi")).isFalse();
    }
  }

  @Test
  void packetLossLosesMessagesAndSaysSo() {
    try (Simulation s = Simulation.builder(TestScenes.boundPair("")).packetLoss(1.0).build()) {
      atom(s, 1).send(Leg.PX, "lost");
      s.runCycle();
      assertThat(s.lastEvents()).containsExactly(new SimEvent.MessageLost(0, 1, Leg.PX));
      s.runCycle();
      assertThat(atom(s, 2).receive()).isEmpty();
      s.setPacketLoss(0);
      atom(s, 1).send(Leg.PX, "through");
      s.runCycle();
      assertThat(atom(s, 2).receive())
          .extracting(ReceivedMessage::payload)
          .containsExactly("through");
    }
  }

  @Test
  void aFailedAtomSensesNothingSendsNothingAndItsControllerStops() {
    int[] runs = {0};
    try (Simulation s =
        Simulation.builder(TestScenes.boundPair("")).controller(2, (b, c) -> runs[0]++).build()) {
      s.runCycle();
      s.failAtom(2);
      s.runCycle();
      assertThat(s.lastEvents()).containsExactly(new SimEvent.AtomFailed(10_000_000, 2));
      s.runCycle();
      assertThat(runs[0]).isEqualTo(1);
      AtomSensors sensors = s.sensors(2);
      assertThat(sensors.failed()).isTrue();
      assertThat(sensors.legs()).allMatch(LegSensors::failed);
      assertThat(atom(s, 2).send(Leg.MX, "hi")).isFalse();
      atom(s, 1).send(Leg.PX, "to the dead");
      s.runCycles(2);
      assertThat(atom(s, 2).receive()).isEmpty();
    }
  }

  @Test
  void aFailedLegGoesLimpAndReadsFailed() {
    try (Simulation s = Simulation.builder(Scenes.parse("gravity 0 0 0\natom 1 0 0 1")).build()) {
      s.failLeg(1, Leg.PZ);
      atom(s, 1).setLegTarget(Leg.PZ, 0.4, 0);
      atom(s, 1).setLegTarget(Leg.PY, 0.4, 0);
      s.runFor(Duration.ofMillis(300));
      s.runCycle();
      assertThat(s.sensors(1).leg(Leg.PZ).failed()).isTrue();
      assertThat(s.sensors(1).leg(Leg.PY).angles().elevation())
          .isCloseTo(0.4, org.assertj.core.data.Offset.offset(0.01));
    }
  }

  @Test
  void badArgumentsAreRefusedWithTheValue() {
    try (Simulation s = Simulation.builder(TestScenes.boundPair("")).build()) {
      org.assertj.core.api.Assertions.assertThatThrownBy(() -> s.setPacketLoss(1.5))
          .hasMessageContaining("1.5");
      org.assertj.core.api.Assertions.assertThatThrownBy(() -> atom(s, 9))
          .hasMessageContaining("no atom 9");
      org.assertj.core.api.Assertions.assertThatThrownBy(
              () -> atom(s, 1).setLegTarget(Leg.PX, Double.NaN, 0))
          .hasMessageContaining("NaN");
      org.assertj.core.api.Assertions.assertThatThrownBy(
              () -> atom(s, 1).setTorqueLimit(Leg.PX, -1))
          .hasMessageContaining("-1.0");
    }
    org.assertj.core.api.Assertions.assertThatThrownBy(
            () ->
                Simulation.builder(TestScenes.boundPair(""))
                    .controlPeriod(Duration.ofMillis(10))
                    .physicsStep(Duration.ofMillis(3))
                    .build())
        .hasMessageContaining("multiple of the physics step");
  }
}

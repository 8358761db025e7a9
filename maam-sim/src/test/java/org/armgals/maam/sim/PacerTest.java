package org.armgals.maam.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import org.armgals.maam.sim.spi.Pacer;
import org.junit.jupiter.api.Test;

class PacerTest {

  @Test
  void aRealTimePacerWaitsUntilRealTimeCatchesUpWithVirtualTime() {
    long[] now = {1_000};
    List<Long> sleeps = new ArrayList<>();
    Pacer pacer =
        Pacer.realTime(
            () -> now[0],
            nanos -> {
              sleeps.add(nanos);
              now[0] += nanos;
            },
            1.0);
    try (Simulation s =
        Simulation.builder(Scenes.parse("gravity 0 0 0\natom 1 0 0 1")).pacer(pacer).build()) {
      s.runCycle(); // first call: sets the origin, 10 ms of virtual time behind
      now[0] += 4_000_000; // the next cycle took 4 ms of real time
      s.runCycle();
      now[0] += 12_000_000; // this one took 12 ms: late, no wait
      s.runCycle();
    }
    assertThat(sleeps).containsExactly(6_000_000L);
  }

  @Test
  void aSleeperThatWakesEarlyIsCalledAgainUntilRealTimeHasCaughtUp() {
    long[] now = {0};
    List<Long> sleeps = new ArrayList<>();
    Pacer pacer =
        Pacer.realTime(
            () -> now[0],
            nanos -> {
              sleeps.add(nanos);
              now[0] += nanos / 2 + 1; // every sleep ends half way
            },
            1.0);
    pacer.pace(0);
    pacer.pace(1_000);
    assertThat(now[0]).isGreaterThanOrEqualTo(1_000);
    assertThat(sleeps).startsWith(1_000L, 499L);
  }

  @Test
  void aPacerAtTwiceRealTimeWaitsHalfAsLong() {
    long[] now = {0};
    List<Long> sleeps = new ArrayList<>();
    Pacer pacer =
        Pacer.realTime(
            () -> now[0],
            nanos -> {
              sleeps.add(nanos);
              now[0] += nanos;
            },
            2.0);
    pacer.pace(0);
    pacer.pace(10_000_000);
    assertThat(sleeps).containsExactly(5_000_000L);
    assertThatThrownBy(() -> Pacer.realTime(() -> 0, n -> {}, 0))
        .hasMessageContaining("pacing speed 0.0");
  }
}

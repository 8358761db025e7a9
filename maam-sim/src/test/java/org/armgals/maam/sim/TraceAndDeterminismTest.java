package org.armgals.maam.sim;

import static org.armgals.maam.sim.TestScenes.joints;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.List;
import java.util.SplittableRandom;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

class TraceAndDeterminismTest {

  /** Runs the chain of four with seeded random targets, messages, loss and faults. */
  private static String trace(LegDynamics dynamics, long seed) {
    StringWriter out = new StringWriter();
    try (Simulation s =
        Simulation.builder(Scenes.builtIn("chain4"))
            .legDynamics(dynamics)
            .seed(seed)
            .packetLoss(0.3)
            .trace(out)
            .controllers(
                id -> {
                  SplittableRandom random = new SplittableRandom(id);
                  return (body, cycle) -> {
                    joints(body).setLegTarget(Leg.MZ, random.nextDouble(-0.5, 0.5), 0.2);
                    joints(body).send(Leg.PX, "c" + cycle);
                    joints(body).send(Leg.MX, "c" + cycle);
                  };
                })
            .build()) {
      s.runCycles(40);
      s.failLeg(2, Leg.MZ);
      s.note(3, "meta: schema \"walk\" replaced");
      s.runCycles(40);
    }
    return out.toString();
  }

  private static String sha256(String text) throws NoSuchAlgorithmException {
    return HexFormat.of()
        .formatHex(
            MessageDigest.getInstance("SHA-256").digest(text.getBytes(StandardCharsets.UTF_8)));
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void sameSeedAndInputsGiveTheSameTraceBitForBit(LegDynamics dynamics)
      throws NoSuchAlgorithmException {
    String first = trace(dynamics, 42);
    String second = trace(dynamics, 42);
    assertThat(sha256(second)).isEqualTo(sha256(first));
    assertThat(sha256(trace(dynamics, 43))).isNotEqualTo(sha256(first));
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void aRunOnSeveralThreadsWritesTheSameTraceAsOnOne(LegDynamics dynamics)
      throws NoSuchAlgorithmException {
    // Close enough for the atoms to collide with each other, not only to overlap boxes.
    int atoms = 3 * Lanes.MIN_PER_LANE;
    TestScenes.CrowdRun three = TestScenes.crowd(dynamics, atoms, 0.12, 3, s -> {});
    TestScenes.CrowdRun one = TestScenes.crowd(dynamics, atoms, 0.12, 1, s -> {});
    assertThat(three.atomContacts()).isPositive().isEqualTo(one.atomContacts());
    assertThat(sha256(three.trace())).isEqualTo(sha256(one.trace()));
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void theTraceHasAHeaderThenOneLinePerCycleWithAtomsAndEvents(LegDynamics dynamics) {
    List<String> lines = trace(dynamics, 7).lines().toList();
    assertThat(lines).hasSize(81);
    assertThat(lines.get(0))
        .startsWith("{\"type\":\"header\",\"format\":\"armgals-maam-sim-trace\",\"version\":1,")
        .contains("\"scene\":\"chain4\"", "\"seed\":7", "\"atoms\":[1,2,3,4]", "\"bindStrength\":");
    assertThat(lines.get(1)).startsWith("{\"type\":\"cycle\",\"cycle\":0,\"t\":0,\"atoms\":[");
    assertThat(lines.get(1)).contains("{\"id\":1,\"p\":[", "\"energy\":", "\"legs\":[[");
    assertThat(lines.get(41))
        .contains("{\"t\":400000000,\"type\":\"legFailed\",\"atom\":2,\"leg\":\"-z\"}")
        .contains(
            "{\"t\":400000000,\"type\":\"note\",\"atom\":3,\"text\":\"meta: schema \\\"walk\\\""
                + " replaced\"}");
    assertThat(String.join("\n", lines)).contains("\"type\":\"messageLost\"");
  }

  @Test
  void traceAttributesGoIntoTheHeaderInTheOrderGiven() {
    StringWriter out = new StringWriter();
    try (Simulation s =
        Simulation.builder(Scenes.builtIn("single"))
            .traceAttribute("example", "walker")
            .traceAttribute("note", "say \"hi\"")
            .trace(out)
            .build()) {
      s.runCycles(1);
    }
    assertThat(out.toString().lines().findFirst().orElseThrow())
        .contains("\"attributes\":{\"example\":\"walker\",\"note\":\"say \\\"hi\\\"\"}");
  }

  @Test
  void aTraceAttributeIsSetOnceAndNamed() {
    SimulationBuilder builder = Simulation.builder(Scenes.builtIn("single"));
    builder.traceAttribute("example", "walker");
    assertThatThrownBy(() -> builder.traceAttribute("example", "caterpillar"))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'example'");
    assertThatThrownBy(() -> builder.traceAttribute(" ", "x"))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("blank");
  }
}

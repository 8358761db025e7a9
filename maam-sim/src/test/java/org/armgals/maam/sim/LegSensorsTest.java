package org.armgals.maam.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.StringWriter;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * A leg's readings speak the framework's {@link LegAngles}: what {@link Simulation#sensors} gives
 * is what the atom's framework body reads, and what a trace gives back.
 */
class LegSensorsTest {

  /** An atom in free space whose legs are driven off their axes through its framework body. */
  private static Simulation turning(LegDynamics dynamics, StringWriter trace) {
    return Simulation.builder(Scenes.parse("gravity 0 0 0\natom 1 0 0 1"))
        .legDynamics(dynamics)
        .trace(trace)
        .controller(
            1,
            (body, cycle) -> {
              for (Leg leg : Leg.values()) {
                body.command(Atom.target(leg), new LegAngles(0.05 * (1 + leg.ordinal()), 0.4));
              }
            })
        .build();
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void aLegsAnglesAreWhatTheFrameworkBodyReads(LegDynamics dynamics) {
    try (Simulation s = turning(dynamics, new StringWriter())) {
      s.runCycles(20);
      Body body = s.body(1);
      for (Leg leg : Leg.values()) {
        LegAngles sensed = s.sensors(1).leg(leg).angles();
        assertThat(sensed.elevation()).as("%s moved", leg).isGreaterThan(0.01);
        assertThat(body.read(Atom.angles(leg))).as("%s", leg).isEqualTo(sensed);
      }
    }
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void aTracedLegReadsBackAsTheRunSensedIt(LegDynamics dynamics) {
    StringWriter trace = new StringWriter();
    List<LegSensors> sensed;
    try (Simulation s = turning(dynamics, trace)) {
      s.runCycles(20);
      sensed = s.sensors(1).legs(); // read at the start of the last cycle, which its line records
    }
    List<String> lines = trace.toString().lines().toList();
    String line = lines.get(lines.size() - 1);
    Matcher arrays = Pattern.compile("\\[([^\\[\\]]*)\\]").matcher(line.split("\"legs\":")[1]);
    List<LegSensors> traced = new ArrayList<>();
    for (Leg leg : Leg.values()) {
      assertThat(arrays.find()).as("%s's array in %s", leg, line).isTrue();
      List<Double> values = Arrays.stream(arrays.group(1).split(",")).map(Double::valueOf).toList();
      traced.add(LegSensors.traced(leg, values));
    }
    assertThat(traced).isEqualTo(sensed);
  }

  @Test
  void aTraceArrayOfTheWrongLengthIsRefused() {
    assertThatThrownBy(() -> LegSensors.traced(Leg.PX, List.of(0.1, 0.2)))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("[0.1, 0.2]")
        .hasMessageContaining("expected 9 numbers");
  }
}

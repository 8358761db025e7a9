package org.armgals.maam.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

class WorldTest {

  @Test
  void proximityMeasuresTheDistanceFromTheTipToAWallAlongTheLeg() {
    // Tip of +x at x = 0.11; the wall's near face at x = 0.31.
    Scene scene = Scenes.parse("gravity 0 0 0\nbox 0.36 0 1 0.1 1 1\natom 1 0 0 1");
    try (Simulation s = Simulation.builder(scene).build()) {
      s.runCycle();
      AtomSensors sensors = s.sensors(1);
      assertThat(sensors.leg(Leg.PX).proximity()).isCloseTo(0.2, offset(1e-6));
      assertThat(sensors.leg(Leg.MX).proximity()).isEqualTo(scene.params().proximityRange());
    }
  }

  @Test
  void anAtomDroppedOnABoxComesToRestOnTopOfIt() {
    Scene scene = Scenes.parse("box 0 0 0.05 0.4 0.4 0.1\natom 1 0 0 0.2 tripod");
    try (Simulation s = Simulation.builder(scene).build()) {
      s.runFor(Duration.ofSeconds(1));
      assertThat(s.sensors(1).position().z()).isBetween(0.15, 0.18);
      assertThat(s.sensors(1).leg(Leg.MZ).tipContact()).isTrue();
    }
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void anAtomDroppedOnAnotherComesToRestOnIt(LegDynamics dynamics) {
    Scene scene = Scenes.parse("atom 1 0 0 0.07 tripod\natom 2 0 0 0.3 tripod");
    try (Simulation s = Simulation.builder(scene).legDynamics(dynamics).build()) {
      s.runFor(Duration.ofSeconds(1));
      // Alone on the ground its kernel would be 0.07 m up; on the other atom it is at least 0.12.
      assertThat(s.sensors(2).position().z()).isGreaterThan(0.12);
    }
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void proximityMeasuresTheDistanceToAnotherAtom(LegDynamics dynamics) {
    // Tip of atom 1's +x at x = 0.11; atom 2's -x tip at x = 0.19.
    Scene scene = Scenes.parse("gravity 0 0 0\natom 1 0 0 1\natom 2 0.3 0 1");
    try (Simulation s = Simulation.builder(scene).legDynamics(dynamics).build()) {
      s.runCycles(2);
      assertThat(s.sensors(1).leg(Leg.PX).proximity()).isCloseTo(0.08, offset(1e-6));
      assertThat(s.sensors(2).leg(Leg.MX).proximity()).isCloseTo(0.08, offset(1e-6));
    }
  }

  @Test
  void atomsInAPipeRestOnItsWallNotOnTheGround() {
    try (Simulation s = Simulation.builder(Scenes.builtIn("pipe")).build()) {
      s.runFor(Duration.ofSeconds(1));
      for (int id : s.atomIds()) {
        Vec3 p = s.sensors(id).position();
        assertThat(p.z()).as("atom %d height", id).isGreaterThan(0.13);
        assertThat(Math.abs(p.y())).as("atom %d off the axis", id).isLessThan(0.16);
      }
    }
  }

  @Test
  void aSceneIsLoadedFromAFile(@TempDir Path dir) throws IOException {
    Path file = dir.resolve("one.scene");
    Files.writeString(file, "scene from-file\natom 4 0 0 0.07 tripod\n");
    Scene scene = Scenes.load(file);
    assertThat(scene.name()).isEqualTo("from-file");
    assertThat(scene.atoms()).extracting(Scene.Placement::id).containsExactly(4);
  }
}

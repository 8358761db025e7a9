package org.armgals.maam.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.armgals.maam.spi.Leg;
import org.junit.jupiter.api.Test;

class ScenesTest {

  @Test
  void everyBuiltInSceneParsesAndBuilds() {
    assertThat(Scenes.builtInNames()).contains("single", "pair", "chain4", "steps", "pipe");
    for (String name : Scenes.builtInNames()) {
      Scene scene = Scenes.builtIn(name);
      assertThat(scene.name()).isEqualTo(name);
      try (Simulation s = Simulation.builder(scene).build()) {
        s.runCycles(2);
        assertThat(s.atomIds()).hasSize(scene.atoms().size());
      }
    }
  }

  @Test
  void parsesEveryKeyword() {
    Scene scene =
        Scenes.parse(
            """
            # a comment
            scene demo
            param bindStrength 80
            param coneHalfAngle 20deg
            param autoLock true
            gravity 0 0 -1.62   # the Moon
            box 1 0 0.05 0.4 1 0.1
            pipe 0 0 0.2 x 0.15 0.01 2
            atom 1 0 0 0.2
            atom 2 0.22 0 0.2 tripod
            atom 3 0.44 0 0.2 0 0 1 90
            bond 1:+x 2:-x
            """);
    assertThat(scene.name()).isEqualTo("demo");
    assertThat(scene.params().bindStrength()).isEqualTo(80);
    assertThat(scene.params().coneHalfAngle()).isCloseTo(Math.toRadians(20), within());
    assertThat(scene.params().autoLock()).isTrue();
    assertThat(scene.gravity()).isEqualTo(new Vec3(0, 0, -1.62));
    assertThat(scene.obstacles())
        .containsExactly(
            new Obstacle.Box(new Vec3(1, 0, 0.05), new Vec3(0.4, 1, 0.1)),
            new Obstacle.Pipe(new Vec3(0, 0, 0.2), 'x', 0.15, 0.01, 2));
    assertThat(scene.atoms()).hasSize(3);
    assertThat(scene.atoms().get(1).orientation()).isEqualTo(Quat.tripod());
    assertThat(scene.bonds()).containsExactly(new Scene.Bond(1, Leg.PX, 2, Leg.MX));
  }

  @Test
  void aBadLineIsNamedWithItsNumberAndWhatWasExpected() {
    assertThatThrownBy(() -> Scenes.parse("scene x\nbox 1 2 3\n"))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("line 2")
        .hasMessageContaining("'box' takes 6 values, not 3");
    assertThatThrownBy(() -> Scenes.parse("wall 1 2 3"))
        .hasMessageContaining("unknown keyword 'wall'");
    assertThatThrownBy(() -> Scenes.parse("param legLength -1"))
        .hasMessageContaining("legLength -1.0");
    assertThatThrownBy(() -> Scenes.parse("param colour 3"))
        .hasMessageContaining("unknown param 'colour'");
    assertThatThrownBy(() -> Scenes.parse("atom 1 0 0 x"))
        .hasMessageContaining("'x' is not a number");
    assertThatThrownBy(() -> Scenes.parse("atom 1 0 0 1\nbond 1:+x 2:-w"))
        .hasMessageContaining("leg label '-w'");
  }

  @Test
  void aSceneRefusesDuplicateIdsAndBondsToMissingAtoms() {
    assertThatThrownBy(() -> Scenes.parse("atom 1 0 0 1\natom 1 1 0 1"))
        .hasMessageContaining("atom id 1 twice");
    assertThatThrownBy(() -> Scenes.parse("atom 1 0 0 1\nbond 1:+x 7:-x"))
        .hasMessageContaining("names atom 7, which is not placed");
  }

  @Test
  void aBondWhoseTipsAreApartIsRefusedWhenTheSimulationIsBuilt() {
    Scene scene = Scenes.parse("atom 1 0 0 1\natom 2 0.5 0 1\nbond 1:+x 2:-x");
    assertThatThrownBy(() -> Simulation.builder(scene).build())
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("bond 1:+x 2:-x joins tips");
  }

  @Test
  void aGridPlacesTheAtomsApart() {
    Scene grid = Scenes.grid(10, 0.4);
    assertThat(grid.atoms()).hasSize(10);
    assertThat(TestScenes.distance(grid.atoms().get(0).position(), grid.atoms().get(1).position()))
        .isCloseTo(0.4, within());
  }

  private static org.assertj.core.data.Offset<Double> within() {
    return org.assertj.core.data.Offset.offset(1e-12);
  }
}

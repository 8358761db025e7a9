package org.armgals.maam.sim;

import static org.armgals.maam.sim.TestScenes.joints;
import static org.armgals.maam.sim.TestScenes.sensorsEachCycle;
import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Rays cast on several lanes at once (decision 0075) read what one lane reads, in a crowd whose
 * rays reach their neighbours, while the atoms fall onto each other and turn their legs.
 */
class RaysOnLanesTest {

  /**
   * {@code count} atoms in tripod pose, 0.21 m apart, in two layers: each second atom 0.3 m up,
   * where the upper legs of the atoms below point their rays (a grid on the ground points them over
   * every atom).
   */
  private static Scene layers(int count) {
    int side = (int) Math.ceil(Math.sqrt(count / 2.0));
    List<Scene.Placement> atoms = new ArrayList<>();
    for (int i = 0; i < count; i++) {
      int k = i / 2;
      Vec3 at = new Vec3((k % side) * 0.21, (k / side) * 0.21, i % 2 == 0 ? 0.07 : 0.3);
      atoms.add(new Scene.Placement(i + 1, at, Quat.tripod()));
    }
    Scene grid = Scenes.grid(1, 1);
    return new Scene("layers", grid.params(), grid.gravity(), List.of(), atoms, List.of());
  }

  /** Every atom's sensors at the start of each of {@code cycles} cycles, on {@code threads}. */
  private static List<AtomSensors> sensed(
      LegDynamics dynamics, int atoms, int threads, int cycles) {
    try (Simulation s =
        Simulation.builder(layers(atoms))
            .legDynamics(dynamics)
            .threads(threads)
            .controllers(
                id -> {
                  SplittableRandom random = new SplittableRandom(id);
                  return (body, cycle) -> {
                    joints(body).setLegTarget(Leg.PX, random.nextDouble(-0.5, 0.5), 0);
                    joints(body).setLegTarget(Leg.PY, random.nextDouble(-0.5, 0.5), 0.2);
                  };
                })
            .build()) {
      return sensorsEachCycle(s, cycles);
    }
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void raysCastOnTwoLanesReadBitForBitWhatOneLaneReads(LegDynamics dynamics) {
    int atoms = 2 * Lanes.MIN_PER_LANE;
    List<AtomSensors> two = sensed(dynamics, atoms, 2, 6);
    List<AtomSensors> one = sensed(dynamics, atoms, 1, 6);
    // Records compare their doubles bit for bit (but NaN).
    assertThat(two).isEqualTo(one);
  }

  @Test
  void theCrowdsRaysOnTwoLanesAskTheGridByRowsOfCells() {
    // So the test above holds the rows (decision 0079) to one lane's readings, on two lanes.
    try (Simulation s = Simulation.builder(layers(2 * Lanes.MIN_PER_LANE)).threads(2).build()) {
      s.runCycle();
      assertThat(((SimulationImpl) s).raysQueriedByRows()).isTrue();
    }
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void inTheCrowdSomeRaysStopAtANeighbour(LegDynamics dynamics) {
    // At the first reading every atom stands as it was placed: a lone atom's rays reach only the
    // ground, so a shorter reading in the crowd is a neighbour.
    List<LegSensors> alone = sensed(dynamics, 1, 1, 1).getFirst().legs();
    int nearer = 0;
    for (AtomSensors atom : sensed(dynamics, 2 * Lanes.MIN_PER_LANE, 2, 1)) {
      for (int l = 0; l < alone.size(); l++) {
        if (atom.legs().get(l).proximity() < alone.get(l).proximity()) {
          nearer++;
        }
      }
    }
    assertThat(nearer).isPositive();
  }
}

package org.armgals.maam.sim;

import static org.armgals.maam.sim.TestScenes.joints;
import static org.armgals.maam.sim.TestScenes.sensorsEachCycle;
import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.SplittableRandom;
import org.armgals.maam.spi.Leg;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * A step without bindings runs the next step's servos in its own drain pass (decision 0073): the
 * run is the same, bit for bit, as with the drain and the servos in passes of their own, on atoms
 * that walk, push and bump into each other.
 */
class FusedPassesTest {

  /** Every atom's sensors after each of {@code cycles} cycles, the passes fused or not. */
  private static List<AtomSensors> sensed(LegDynamics dynamics, boolean fused, int cycles) {
    try (Simulation s =
        Simulation.builder(Scenes.grid(9, 0.21))
            .legDynamics(dynamics)
            .controllers(
                id -> {
                  SplittableRandom random = new SplittableRandom(id);
                  return (body, cycle) -> {
                    joints(body).setLegTarget(Leg.PX, random.nextDouble(-0.6, 0.6), 0.1);
                    joints(body).setLegTarget(Leg.MY, random.nextDouble(-0.6, 0.6), 0.3);
                    joints(body).setLegTarget(Leg.PZ, random.nextDouble(-0.6, 0.6), 0.2);
                  };
                })
            .build()) {
      if (!fused) {
        ((SimulationImpl) s).separatePasses();
      }
      return sensorsEachCycle(s, cycles);
    }
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void fusedDrainAndServoPassesRunBitForBitAsSeparateOnes(LegDynamics dynamics) {
    List<AtomSensors> fused = sensed(dynamics, true, 30);
    List<AtomSensors> separate = sensed(dynamics, false, 30);
    // Records compare their doubles bit for bit (but NaN); the atoms did move.
    assertThat(fused).isEqualTo(separate);
    assertThat(fused.getLast()).isNotEqualTo(fused.get(fused.size() - 1 - 9 * 29));
  }
}

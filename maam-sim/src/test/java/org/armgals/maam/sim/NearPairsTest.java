package org.armgals.maam.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The lists of near pairs (decision 0076) give each step the pairs, in the order, that filing every
 * box in the grid and searching it gives: for boxes that wander, jump and grow, and in a crowd of
 * atoms that bump into each other, whose runs stay the same bit for bit.
 */
class NearPairsTest {

  /** {@code count} boxes 0.22 m wide, 0.2 m apart on a square, so that neighbours overlap. */
  private static double[] crowd(int count) {
    int side = (int) Math.ceil(Math.sqrt(count));
    double[] boxes = new double[6 * count];
    for (int i = 0; i < count; i++) {
      double[] centre = {(i % side) * 0.2, (i / side) * 0.2, 0.1};
      for (int axis = 0; axis < 3; axis++) {
        boxes[6 * i + 2 * axis] = centre[axis] - 0.11;
        boxes[6 * i + 2 * axis + 1] = centre[axis] + 0.11;
      }
    }
    return boxes;
  }

  /** Each atom's pairs, atom by atom, as the grid gives them with every box filed. */
  private static List<String> searched(AtomGrid grid, double[] boxes, int count) {
    grid.rebuild(boxes, count);
    List<String> pairs = new ArrayList<>();
    for (int a = 0; a < count; a++) {
      grid.forEachPairOf(a, (x, b) -> pairs.add(x + "-" + b));
    }
    return pairs;
  }

  /** The same from the lists, {@code grid}'s cells fitted. */
  private static List<String> listed(NearPairs near, AtomGrid grid, double[] boxes, int count) {
    assertThat(near.update(boxes, count)).isTrue();
    grid.fitCells(boxes, count);
    List<String> pairs = new ArrayList<>();
    for (int a = 0; a < count; a++) {
      near.forEachPairOf(a, boxes, grid, (x, b) -> pairs.add(x + "-" + b));
    }
    return pairs;
  }

  @Test
  void givesThePairsTheGridGivesInItsOrderWhileTheBoxesWanderJumpAndGrow() {
    int count = 400;
    double[] boxes = crowd(count);
    SplittableRandom random = new SplittableRandom(17);
    AtomGrid searchedGrid = new AtomGrid();
    AtomGrid listedGrid = new AtomGrid();
    NearPairs near = new NearPairs();
    int pairs = 0;
    int atomsWithSeveral = 0;
    for (int step = 0; step < 200; step++) {
      for (int i = 0; i < count; i++) {
        // Most boxes creep a millimetre, some jump 5 cm (past the lists' room), a few grow.
        double jump = random.nextInt(50) == 0 ? 0.05 : 0.001;
        double dx = random.nextDouble(-jump, jump);
        double dy = random.nextDouble(-jump, jump);
        double grow = random.nextInt(500) == 0 ? 0.01 : 0;
        boxes[6 * i] += dx - grow;
        boxes[6 * i + 1] += dx + grow;
        boxes[6 * i + 2] += dy;
        boxes[6 * i + 3] += dy;
      }
      List<String> expected = searched(searchedGrid, boxes, count);
      List<String> found = listed(near, listedGrid, boxes, count);
      assertThat(found).as("step %d", step).containsExactlyElementsOf(expected);
      pairs += expected.size();
      for (int a = 0; a < count; a++) {
        String prefix = a + "-";
        if (expected.stream().filter(p -> p.startsWith(prefix)).count() > 1) {
          atomsWithSeveral++;
        }
      }
    }
    // The order was put to the test: atoms had several pairs, in several of the grid's cells.
    assertThat(pairs).isGreaterThan(100_000);
    assertThat(atomsWithSeveral).isGreaterThan(10_000);
  }

  @Test
  void aBoxThatIsNotFiniteLeavesTheSearchToTheGrid() {
    double[] boxes = crowd(10);
    NearPairs near = new NearPairs();
    assertThat(near.update(boxes, 10)).isTrue();
    boxes[6 * 3 + 1] = Double.NaN;
    assertThat(near.update(boxes, 10)).isFalse();
    boxes[6 * 3 + 1] = Double.POSITIVE_INFINITY;
    assertThat(near.update(boxes, 10)).isFalse();
  }

  @ParameterizedTest
  @EnumSource(LegDynamics.class)
  void aCrowdRunsBitForBitAsWithTheGridSearchedEveryStep(LegDynamics dynamics) {
    TestScenes.CrowdRun listed = TestScenes.crowd(dynamics, 25, 0.12, 1, s -> {});
    TestScenes.CrowdRun searched =
        TestScenes.crowd(dynamics, 25, 0.12, 1, SimulationImpl::searchEveryStep);
    assertThat(listed.atomContacts()).isPositive();
    assertThat(listed).isEqualTo(searched);
  }
}

package org.armgals.maam.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class AtomGridTest {

  /**
   * {@code count} boxes (see {@link Boxes}) of random sizes, a tenth of {@code largest} m to all of
   * it, scattered over a 4 m square, some stacked.
   */
  private static double[] boxes(long seed, int count, double largest) {
    SplittableRandom random = new SplittableRandom(seed);
    double[] boxes = new double[6 * count];
    for (int i = 0; i < count; i++) {
      double[] centre = {
        random.nextDouble(-2, 2), random.nextDouble(-2, 2), random.nextDouble(0, 0.3)
      };
      for (int axis = 0; axis < 3; axis++) {
        double half = random.nextDouble(largest / 10, largest) / 2;
        boxes[6 * i + 2 * axis] = centre[axis] - half;
        boxes[6 * i + 2 * axis + 1] = centre[axis] + half;
      }
    }
    return boxes;
  }

  private static List<String> pairsByBruteForce(double[] boxes) {
    List<String> pairs = new ArrayList<>();
    for (int a = 0; a < boxes.length / 6; a++) {
      for (int b = a + 1; b < boxes.length / 6; b++) {
        if (Boxes.overlap(boxes, 6 * a, boxes, 6 * b)) {
          pairs.add(a + "-" + b);
        }
      }
    }
    return pairs;
  }

  private static List<String> pairs(AtomGrid grid) {
    List<String> found = new ArrayList<>();
    grid.forEachPair((a, b) -> found.add(a + "-" + b));
    return found;
  }

  @Test
  void findsExactlyThePairsWhoseBoxesOverlapEachOnce() {
    for (long seed = 1; seed <= 20; seed++) {
      double[] boxes = boxes(seed, 300, 0.3);
      AtomGrid grid = new AtomGrid();
      grid.rebuild(boxes, 300);
      assertThat(pairs(grid))
          .as("seed %d", seed)
          .isNotEmpty()
          .containsExactlyInAnyOrderElementsOf(pairsByBruteForce(boxes));
    }
  }

  @Test
  void findsExactlyTheAtomsWhoseBoxesOverlapAQueryOfAnySize() {
    double[] boxes = boxes(7, 300, 0.25);
    AtomGrid grid = new AtomGrid();
    grid.rebuild(boxes, 300);
    for (double size : new double[] {0.01, 0.5, 3, 100}) {
      double[] queries = boxes(size > 1 ? 11 : 13, 40, size);
      for (int q = 0; q < 40; q++) {
        double[] query = Arrays.copyOfRange(queries, 6 * q, 6 * q + 6);
        List<Integer> expected = new ArrayList<>();
        for (int a = 0; a < 300; a++) {
          if (Boxes.overlap(boxes, 6 * a, query, 0)) {
            expected.add(a);
          }
        }
        List<Integer> found = new ArrayList<>();
        grid.forEachOverlapping(query, found::add);
        assertThat(found).containsExactlyInAnyOrderElementsOf(expected);
      }
    }
  }

  /** The atoms whose boxes overlap {@code query}, by brute force, then by the grid's query. */
  private static void assertQueryFindsTheOverlapping(
      AtomGrid grid, double[] boxes, double[] query, String what) {
    List<Integer> expected = new ArrayList<>();
    for (int a = 0; a < boxes.length / 6; a++) {
      if (Boxes.overlap(boxes, 6 * a, query, 0)) {
        expected.add(a);
      }
    }
    List<Integer> found = new ArrayList<>();
    grid.forEachOverlapping(query, found::add);
    assertThat(found).as(what).containsExactlyInAnyOrderElementsOf(expected);
  }

  @Test
  void queriesByRowsOfCellsFindWhatTheHashFindsAsBoxesMove() {
    // A thousand atoms on a square grid 0.4 m apart, as the benchmark lays them out, queried with
    // boxes the size of an atom's reach: by rows of cells. Then some jump far away, which spreads
    // the cells too thin for rows: through the hash of cells. Then back. (The other query test
    // files no rows: the hash alone.)
    SplittableRandom random = new SplittableRandom(17);
    int count = 1000;
    double[] boxes = new double[6 * count];
    AtomGrid grid = new AtomGrid();
    for (int round = 0; round < 30; round++) {
      boolean far = round % 3 == 1;
      for (int i = 0; i < count; i++) {
        double x = (i % 32) * 0.4 + random.nextDouble(-0.05, 0.05);
        double y = (i / 32) * 0.4 + random.nextDouble(-0.05, 0.05);
        if (far && i % 100 == 0) {
          x += random.nextDouble(-1e4, 1e4);
          y += random.nextDouble(-1e4, 1e4);
        }
        double half = random.nextDouble(0.08, 0.11);
        double[] box = {x - half, x + half, y - half, y + half, 0, 0.2};
        System.arraycopy(box, 0, boxes, 6 * i, 6);
      }
      grid.rebuild(boxes, count);
      grid.fileRows();
      for (int q = 0; q < 50; q++) {
        double x = random.nextDouble(-1, 14);
        double y = random.nextDouble(-1, 14);
        double h = random.nextDouble(0.01, 0.7);
        double[] query = {x - h, x + h, y - h, y + h, random.nextDouble(-0.1, 0.1), 0.3};
        assertQueryFindsTheOverlapping(grid, boxes, query, "round " + round + " query " + q);
        assertThat(grid.queriedByRows()).as("round %d", round).isEqualTo(!far);
      }
      // A box that is not finite overlaps nothing, and is found by no query.
      boxes[6 * 5] = Double.NaN;
      grid.rebuild(boxes, count);
      grid.fileRows();
      assertQueryFindsTheOverlapping(grid, boxes, new double[] {-1, 14, -1, 14, -1, 1}, "NaN");
    }
  }

  @Test
  void givesThePairsInTheSameOrderEveryTime() {
    AtomGrid grid = new AtomGrid();
    grid.rebuild(boxes(3, 500, 0.3), 500);
    AtomGrid other = new AtomGrid();
    other.rebuild(boxes(3, 500, 0.3), 500);
    assertThat(pairs(other)).isNotEmpty().containsExactlyElementsOf(pairs(grid));
  }

  @Test
  void followsABoxThatMovesAndGrowsBetweenSteps() {
    double[] boxes = boxes(5, 50, 0.2);
    AtomGrid grid = new AtomGrid();
    grid.rebuild(boxes, 50);
    // Box 0 becomes 2 m wide in x and y, centred at (0.5, -0.5).
    double[] grown = {-0.5, 1.5, -1.5, 0.5, 0, 0.3};
    System.arraycopy(grown, 0, boxes, 0, 6);
    grid.rebuild(boxes, 50);
    List<String> found = pairs(grid);
    assertThat(found.stream().filter(p -> p.startsWith("0-")).count()).isGreaterThan(1);
    assertThat(found).containsExactlyInAnyOrderElementsOf(pairsByBruteForce(boxes));
  }
}

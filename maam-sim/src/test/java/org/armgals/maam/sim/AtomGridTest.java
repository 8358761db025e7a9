package org.armgals.maam.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.ode4j.ode.DAABBC;
import org.ode4j.ode.DBox;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.OdeHelper;

class AtomGridTest {

  /**
   * Boxes of random sizes (a tenth of {@code largest} m to all of it) scattered over a 4 m square,
   * some stacked.
   */
  private static List<DGeom> boxes(long seed, int count, double largest) {
    SplittableRandom random = new SplittableRandom(seed);
    List<DGeom> boxes = new ArrayList<>();
    for (int i = 0; i < count; i++) {
      DBox box =
          OdeHelper.createBox(
              null,
              random.nextDouble(largest / 10, largest),
              random.nextDouble(largest / 10, largest),
              random.nextDouble(largest / 10, largest));
      box.setPosition(
          random.nextDouble(-2, 2), random.nextDouble(-2, 2), random.nextDouble(0, 0.3));
      boxes.add(box);
    }
    return boxes;
  }

  private static boolean overlap(DAABBC a, DAABBC b) {
    return !a.isDisjoint(b);
  }

  @Test
  void findsExactlyThePairsWhoseBoxesOverlapEachOnce() {
    for (long seed = 1; seed <= 20; seed++) {
      List<DGeom> boxes = boxes(seed, 300, 0.3);
      List<String> expected = new ArrayList<>();
      for (int a = 0; a < boxes.size(); a++) {
        for (int b = a + 1; b < boxes.size(); b++) {
          if (overlap(boxes.get(a).getAABB(), boxes.get(b).getAABB())) {
            expected.add(a + "-" + b);
          }
        }
      }
      AtomGrid grid = new AtomGrid();
      grid.rebuild(boxes);
      List<String> found = new ArrayList<>();
      grid.forEachPair((a, b) -> found.add(a + "-" + b));
      assertThat(found).as("seed %d", seed).containsExactlyInAnyOrderElementsOf(expected);
    }
  }

  @Test
  void findsExactlyTheAtomsWhoseBoxesOverlapAQueryOfAnySize() {
    List<DGeom> boxes = boxes(7, 300, 0.25);
    AtomGrid grid = new AtomGrid();
    grid.rebuild(boxes);
    for (double size : new double[] {0.01, 0.5, 3, 100}) {
      for (DGeom query : boxes(size > 1 ? 11 : 13, 40, size)) {
        List<Integer> expected = new ArrayList<>();
        for (int a = 0; a < boxes.size(); a++) {
          if (overlap(boxes.get(a).getAABB(), query.getAABB())) {
            expected.add(a);
          }
        }
        List<Integer> found = new ArrayList<>();
        grid.forEachOverlapping(query.getAABB(), found::add);
        assertThat(found).containsExactlyInAnyOrderElementsOf(expected);
      }
    }
  }

  @Test
  void givesThePairsInTheSameOrderEveryTime() {
    List<String> first = new ArrayList<>();
    List<String> second = new ArrayList<>();
    AtomGrid grid = new AtomGrid();
    grid.rebuild(boxes(3, 500, 0.3));
    grid.forEachPair((a, b) -> first.add(a + "-" + b));
    AtomGrid other = new AtomGrid();
    other.rebuild(boxes(3, 500, 0.3));
    other.forEachPair((a, b) -> second.add(a + "-" + b));
    assertThat(second).isNotEmpty().containsExactlyElementsOf(first);
  }

  @Test
  void followsABoxThatMovesAndGrowsBetweenSteps() {
    List<DGeom> boxes = boxes(5, 50, 0.2);
    AtomGrid grid = new AtomGrid();
    grid.rebuild(boxes);
    DBox grown = (DBox) boxes.get(0);
    grown.setPosition(0.5, -0.5, 0.1);
    grown.setLengths(2, 2, 0.5);
    grid.rebuild(boxes);
    List<Integer> expected = new ArrayList<>();
    for (int b = 1; b < boxes.size(); b++) {
      if (overlap(grown.getAABB(), boxes.get(b).getAABB())) {
        expected.add(b);
      }
    }
    List<Integer> found = new ArrayList<>();
    grid.forEachPair(
        (a, b) -> {
          if (a == 0) {
            found.add(b);
          }
        });
    assertThat(found).isNotEmpty().containsExactlyInAnyOrderElementsOf(expected);
  }
}

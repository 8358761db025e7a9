package org.armgals.examples.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.List;
import org.armgals.examples.plot.AtomView;
import org.armgals.examples.plot.Point;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;
import org.junit.jupiter.api.Test;

/** A recording's samples are timed by their readings, the first being the scene's initial pose. */
class RecordingTest {

  @Test
  void theFirstSampleIsTheScenesInitialPoseAndReadingsAreNotKeptTwice() {
    Scene scene = Scenes.grid(2, 0.4);
    Scene.Placement placed = scene.atoms().get(1);
    Recording recording = new Recording(scene.params());
    try (Simulation sim = Simulation.builder(scene).build()) {
      recording.sample(sim);
      sim.runCycle(); // its readings are those of its start: the initial pose again
      recording.sample(sim);
      assertThat(recording.paths().get(placed.id()))
          .containsExactly(new Point(placed.position().x(), placed.position().y()));
      AtomView first = recording.first().get(1);
      assertThat(first.centre())
          .isEqualTo(
              new AtomView.Vec(
                  placed.position().x(), placed.position().y(), placed.position().z()));

      sim.runCycles(2);
      recording.sample(sim);
      recording.end(sim.timeNanos());
    }
    assertThat(recording.energy()).extracting(Point::x).containsExactly(0.0, 0.02);
    assertThat(recording.lastSeconds()).isEqualTo(0.02);
    assertThat(recording.seconds()).isEqualTo(0.03);
  }

  @Test
  void aPathsLengthIsTheSumOfItsStepsNotTheStraightLineFromItsStartToItsEnd() {
    List<Point> halfCircle = new ArrayList<>();
    for (int i = 0; i <= 1000; i++) {
      double a = Math.PI * i / 1000;
      halfCircle.add(new Point(0.1 * Math.cos(a), 0.1 * Math.sin(a)));
    }
    assertThat(Recording.length(halfCircle)).isCloseTo(Math.PI * 0.1, within(1e-5));
    assertThat(Recording.length(List.of(new Point(1, 1)))).isZero();
  }

  @Test
  void theSummaryGivesTheCentresPathLengthBesideItsDisplacement() {
    Scene scene = Scenes.builtIn("single");
    Recording recording = new Recording(scene.params());
    try (Simulation sim = Simulation.builder(scene).build()) {
      for (int i = 0; i < 30; i++) {
        sim.runCycle();
        recording.sample(sim);
      }
      recording.end(sim.timeNanos());
    }
    List<Point> path = recording.paths().values().iterator().next();
    assertThat(recording.pathLength()).isEqualTo(Recording.length(path));
    assertThat(recording.pathLength()).isGreaterThanOrEqualTo(recording.displacement());
    var entries =
        recording.summary(0, List.of(), java.nio.file.Path.of("out")).entries().stream()
            .map(e -> e.name())
            .toList();
    assertThat(entries).containsSubsequence("displacement", "path length");
  }
}

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
  void aPathsLengthFollowsItsTurnsButNotItsWobbles() {
    List<Point> halfCircle = new ArrayList<>();
    List<Point> wobbling = new ArrayList<>();
    for (int i = 0; i <= 1000; i++) {
      double a = Math.PI * i / 1000;
      halfCircle.add(new Point(0.5 * Math.cos(a), 0.5 * Math.sin(a)));
      // the same half circle, rocking 1 cm to and fro 50 times on the way
      double rock = 0.01 * Math.sin(a * 100);
      wobbling.add(new Point((0.5 + rock) * Math.cos(a), (0.5 + rock) * Math.sin(a)));
    }
    double arc = Math.PI * 0.5;
    assertThat(Recording.length(halfCircle, 0.055)).isCloseTo(arc, within(arc * 0.002));
    assertThat(Recording.length(wobbling, 0.055)).isCloseTo(arc, within(arc * 0.05));
    assertThat(Recording.length(wobbling, 0)).as("every wobble counted").isGreaterThan(arc * 1.5);
    assertThat(Recording.length(List.of(new Point(0, 0), new Point(0.01, 0)), 0.055))
        .as("a path shorter than the resolution: start to end")
        .isCloseTo(0.01, within(1e-12));
    assertThat(Recording.length(List.of(), 0.055)).isZero();
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
    assertThat(recording.pathLength())
        .isEqualTo(Recording.length(path, recording.atomDiameter() / 4));
    assertThat(recording.pathLength()).isGreaterThanOrEqualTo(recording.displacement());
    var entries =
        recording.summary(0, List.of(), java.nio.file.Path.of("out")).entries().stream()
            .map(e -> e.name())
            .toList();
    assertThat(entries).containsSubsequence("displacement", "path length");
  }
}

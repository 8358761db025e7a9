package org.armgals.examples.sim;

import static org.assertj.core.api.Assertions.assertThat;

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
}

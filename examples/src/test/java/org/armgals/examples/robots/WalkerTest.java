package org.armgals.examples.robots;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import org.armgals.examples.robots.GaitsTestSupport.TestJournal;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.Crew;
import org.armgals.examples.sim.Reflection;
import org.armgals.maam.sim.AtomSensors;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.sim.Vec3;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class WalkerTest {

  /** A shove that tips the tripod well past the reflex's limit. */
  private static final Vec3 PUSH = new Vec3(20, 20, 0);

  private static final int PUSH_CYCLES = 5;

  private final Walker walker = new Walker();

  @Test
  void loneAtomShufflesAlongItsHeadingWithoutToppling() {
    RunSettings settings = GaitsTestSupport.settings(Optional.empty());
    try (Simulation sim = Simulation.builder(walker.scene(settings)).build()) {
      int id = sim.atomIds().get(0);
      Vec3 start = sim.sensors(id).position();
      try (Crew crew = walker.start(sim, settings, new TestJournal(sim::timeNanos))) {
        sim.runCycles(300); // 3 s
        assertThat(figure(crew.figures(), "module errors")).isEqualTo("0");
      }
      AtomSensors end = sim.sensors(id);
      double along =
          (end.position().x() - start.x()) * Math.cos(WalkerTuning.HEADING)
              + (end.position().y() - start.y()) * Math.sin(WalkerTuning.HEADING);
      // About 4 cm with the atom of today.
      assertThat(along).isGreaterThan(0.02);
      // Still on its tripod: the kernel well off the ground, leaning less than the reflex allows.
      assertThat(end.position().z()).isGreaterThan(0.04);
      assertThat(end.tilt()).isLessThan(0.6);
    }
  }

  @Test
  void balanceReflexSuppressesTheGaitWhenTheAtomIsKnockedOver(@TempDir Path out) throws Exception {
    RunSettings settings = GaitsTestSupport.settings(Optional.empty());
    try (Simulation sim = Simulation.builder(walker.scene(settings)).build()) {
      int id = sim.atomIds().get(0);
      TestJournal journal = new TestJournal(sim::timeNanos);
      try (Crew crew = walker.start(sim, settings, journal)) {
        sim.runCycles(20);
        for (int i = 0; i < PUSH_CYCLES; i++) {
          sim.push(id, PUSH);
          sim.runCycle();
        }
        sim.runCycles(30);
        List<Summary.Entry> loop = crew.reflection().orElseThrow().finish(out);
        assertThat(figure(loop, "balance reflex")).doesNotStartWith("0 ");
      }
      assertThat(Files.readString(out.resolve(Reflection.LOOP)))
          .contains("balance reflex suppresses the gait");
    }
  }

  @Test
  void atomsOptionIsRefusedNamingTheCaterpillar() {
    assertThatThrownBy(() -> walker.scene(GaitsTestSupport.settings(Optional.of(3))))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("--atoms 3")
        .hasMessageContaining("caterpillar");
  }

  @Test
  void runLeavesTraceAndPictures(@TempDir Path out) {
    Summary summary =
        walker.run(
            GaitsTestSupport.settings(Optional.empty(), OptionalLong.of(100), out),
            new PrintStream(OutputStream.nullOutputStream()));
    assertThat(figure(summary.entries(), "simulated time")).isEqualTo("1.00 s");
    assertThat(summary.entries()).anyMatch(e -> e.name().equals("progress along the heading"));
    for (String file : List.of("trace.jsonl", "trajectory.png", "molecule-end.png")) {
      assertThat(out.resolve(file)).as(file).exists();
    }
  }

  private static String figure(List<Summary.Entry> entries, String name) {
    return entries.stream()
        .filter(e -> e.name().equals(name))
        .map(Summary.Entry::value)
        .findFirst()
        .orElseThrow(() -> new AssertionError("no figure '" + name + "' in " + entries));
  }
}

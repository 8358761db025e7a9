package org.armgals.examples.robots;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.Journal;
import org.armgals.maam.Schema;
import org.armgals.maam.sim.Simulation;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code obstacle} runs briefly in virtual time; each test checks what the chain achieved. */
class ObstacleRobotTest {
  private static final ObstacleRobot OBSTACLE = new ObstacleRobot();

  @TempDir Path dir;

  @Test
  void withoutItsMetaLevelTheChainStallsAgainstTheStep() {
    RunSettings settings = settings(OptionalLong.empty());
    TestJournal journal = new TestJournal();
    try (Simulation sim = Simulation.builder(OBSTACLE.scene(settings)).build()) {
      journal.sim = sim;
      ObstacleCrew crew = OBSTACLE.start(sim, settings, journal, false);
      double start = crew.centre();
      sim.runFor(Duration.ofSeconds(5));
      // It reached the step (it crawls), then pushed against it without getting over.
      assertThat(crew.centre() - start).isGreaterThan(0.08);
      assertThat(front(sim)).isLessThan(ObstacleGait.STEP_FACE + 0.02);
      assertThat(crew.centre()).isLessThan(ObstacleGait.STEP_FACE - 0.15);
      assertThat(journal.adaptations).isEmpty();
      assertThat(crew.robots().get(2).schedule().names()).doesNotContain("carry");
    }
  }

  @Test
  void metaLevelAddsLiftFrontOnceAfterNoProgressAndTheChainGetsOver() {
    RunSettings settings = settings(OptionalLong.empty());
    TestJournal journal = new TestJournal();
    try (Simulation sim = Simulation.builder(OBSTACLE.scene(settings)).build()) {
      journal.sim = sim;
      ObstacleCrew crew = OBSTACLE.start(sim, settings, journal, true);
      long end = Duration.ofSeconds(20).toNanos();
      while (crew.centre() <= ObstacleGait.STEP_FACE && sim.timeNanos() < end) {
        sim.runCycles(10);
      }
      assertThat(crew.centre())
          .as("the molecule's centre passed the step's edge")
          .isGreaterThan(ObstacleGait.STEP_FACE);
      // Once per atom's robot, all at the same time, after a window without progress.
      // Once per atom's robot: the schema and its three connectors, for one reason.
      assertThat(journal.adaptations)
          .hasSize(ObstacleGait.ATOMS)
          .allSatisfy(
              a ->
                  assertThat(a)
                      .contains("addSchema lift-front {edge=")
                      .contains("addConnector lift-front-suppresses-cruise")
                      .contains("no progress for 2.0 s"));
      // Decided on the front atom's state: the front applies it at its next adaptation point,
      // the atoms behind it, whose instant had closed already, one cycle later.
      long period = settings.period().toNanos();
      assertThat(journal.times.get(journal.times.size() - 1) - journal.times.get(0))
          .isBetween(0L, period);
      assertThat(journal.times.get(0)).isGreaterThan(Duration.ofSeconds(3).toNanos());
      for (ObstacleAtom robot : crew.robots()) {
        assertThat(robot.schedule().names()).contains("carry");
        assertThat(robot.metaRobot().schemas().stream().map(Schema::name).toList())
            .contains("lift-front");
        assertThat(robot.errors()).isZero();
      }
    }
  }

  @Test
  void aRunLeavesItsOutputsAndTellsTheAdaptationInItsSummary() {
    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    Summary summary =
        OBSTACLE.run(
            settings(OptionalLong.of(500)), new PrintStream(bytes, true, StandardCharsets.UTF_8));
    assertThat(summary.entries())
        .anySatisfy(e -> assertThat(e.name()).isEqualTo("adaptations"))
        .anySatisfy(e -> assertThat(e.value()).contains("addSchema lift-front"));
    assertThat(dir.resolve("trace.jsonl")).isNotEmptyFile();
    assertThat(dir.resolve("trajectory.png")).isNotEmptyFile();
    assertThat(dir.resolve("adaptations.png")).isNotEmptyFile();
    assertThat(dir.resolve("molecule-end.png")).isNotEmptyFile();
  }

  @Test
  void atomsOptionIsRefusedSayingWhy() {
    RunSettings settings =
        new RunSettings(
            OptionalLong.empty(),
            Optional.empty(),
            Duration.ofMillis(10),
            1,
            Optional.of(5),
            false,
            Optional.empty(),
            dir);
    assertThatThrownBy(() -> OBSTACLE.scene(settings))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("--atoms");
  }

  private RunSettings settings(OptionalLong cycles) {
    return new RunSettings(
        cycles,
        Optional.empty(),
        Duration.ofMillis(10),
        1,
        Optional.empty(),
        false,
        Optional.empty(),
        dir);
  }

  private static double front(Simulation sim) {
    List<Integer> ids = sim.atomIds();
    return sim.sensors(ids.get(ids.size() - 1)).position().x();
  }

  /** Keeps what the crew tells, with the virtual time it was told at. */
  private static final class TestJournal implements Journal {
    Simulation sim;
    final List<String> adaptations = new ArrayList<>();
    final List<Long> times = new ArrayList<>();

    @Override
    public void adaptation(int atom, String what, String why) {
      adaptations.add(atom + ": " + what + ", because " + why);
      times.add(sim.timeNanos());
    }

    @Override
    public void note(int atom, String text) {}
  }
}

package org.armgals.examples.robots;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import org.armgals.examples.robots.GaitsTestSupport.TestJournal;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.maam.sim.Scenes;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegBinding;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code reconfigure} runs briefly in virtual time; each test checks what the molecule did. */
class ReconfigureTest {
  private static final Reconfigure RECONFIGURE = new Reconfigure();

  @TempDir Path dir;

  @Test
  void inTheCorridorTheChainSplitsIntoTwoPairsWhoseSchemasFollowTheirNewPlaces() {
    RunSettings settings = GaitsTestSupport.settings(Optional.empty());
    try (Simulation sim = Simulation.builder(RECONFIGURE.scene(settings)).build()) {
      TestJournal journal = new TestJournal(sim::timeNanos);
      ReconfigureCrew crew = RECONFIGURE.startCrew(sim, settings, journal);
      sim.runCycles(1);
      assertThat(crew.bonds()).isEqualTo(3);
      assertThat(crew.molecules()).containsExactly(List.of(1, 2, 3, 4));
      assertThat(names(crew, 2)).contains("listen", "follow", "relay").doesNotContain("pacemaker");
      assertThat(names(crew, 3)).contains("listen", "follow", "relay");

      long end = Duration.ofSeconds(6).toNanos();
      while (crew.meta().stage() != ReconfigureMeta.Stage.SPLIT && sim.timeNanos() < end) {
        sim.runCycles(1);
      }
      // The terrain change: the front atom had just entered the corridor.
      assertThat(crew.meta().stage()).isEqualTo(ReconfigureMeta.Stage.SPLIT);
      assertThat(crew.meta().splitAt()).isGreaterThan(Duration.ofSeconds(1).toNanos());
      sim.runCycles(2); // the tail's adaptations apply at the end of its next cycle
      assertThat(x(sim, 4))
          .isBetween(ReconfigureTuning.CORRIDOR_START, ReconfigureTuning.CORRIDOR_START + 0.15);
      assertThat(journal.adaptations)
          .hasSize(4)
          .satisfiesExactly(
              a -> assertThat(a).contains("atom 2: addSchema detach {leg=PX}", "a corridor"),
              a -> assertThat(a).contains("atom 3: addSchema detach {leg=MX}", "a corridor"),
              a ->
                  assertThat(a)
                      .contains("atom 2: removeSchema detach; removeSchema follow; addSchema pace")
                      .contains("bond is gone"),
              a ->
                  assertThat(a)
                      .contains("atom 3: removeSchema detach; removeSchema relay", "bond is gone"));

      // The shape: two pairs, as the atoms' binding sensors say.
      assertThat(crew.bonds()).isEqualTo(2);
      assertThat(crew.molecules()).containsExactly(List.of(1, 2), List.of(3, 4));
      assertThat(binding(sim, 2, Leg.PX)).isEqualTo(LegBinding.FREE);
      assertThat(binding(sim, 3, Leg.MX)).isEqualTo(LegBinding.FREE);
      assertThat(binding(sim, 1, Leg.PX)).isEqualTo(new LegBinding.Bound("a2", Leg.MX));
      assertThat(binding(sim, 3, Leg.PX)).isEqualTo(new LegBinding.Bound("a4", Leg.MX));

      // The software: a new head with its own pacemaker, a tail without relay, no detach left.
      assertThat(names(crew, 2))
          .containsExactly("chain", "pacemaker", "crawl", "feet", "relay")
          .doesNotContain("listen", "follow", "detach");
      assertThat(names(crew, 3)).containsExactly("chain", "listen", "follow", "crawl", "feet");
      assertThat(names(crew, 1)).containsExactly("chain", "listen", "follow", "crawl", "feet");
      assertThat(names(crew, 4))
          .containsExactly("chain", "pacemaker", "crawl", "feet", "relay", "survey");
      for (ReconfigureAtom robot : crew.robots()) {
        assertThat(robot.errors()).isZero();
      }

      // Each molecule goes on forward: about 0.3 m in 3 s was seen.
      double rear = crew.centre(List.of(1, 2));
      double front = crew.centre(List.of(3, 4));
      sim.runFor(Duration.ofSeconds(3));
      assertThat(crew.centre(List.of(1, 2)) - rear).isGreaterThan(0.15);
      assertThat(crew.centre(List.of(3, 4)) - front).isGreaterThan(0.15);
      assertThat(crew.molecules()).containsExactly(List.of(1, 2), List.of(3, 4));
      assertThat(journal.adaptations).hasSize(4);
    }
  }

  @Test
  void onOpenGroundTheChainStaysOneMoleculeWithItsSchemas() {
    RunSettings settings = GaitsTestSupport.settings(Optional.empty());
    try (Simulation sim = Simulation.builder(Scenes.parse(Reconfigure.sceneText(false))).build()) {
      TestJournal journal = new TestJournal(sim::timeNanos);
      ReconfigureCrew crew = RECONFIGURE.startCrew(sim, settings, journal);
      sim.runFor(Duration.ofSeconds(4));
      // The front atom is past where the corridor would begin, and nothing happened.
      assertThat(x(sim, 4)).isGreaterThan(ReconfigureTuning.CORRIDOR_START + 0.1);
      assertThat(crew.meta().stage()).isEqualTo(ReconfigureMeta.Stage.CHAIN);
      assertThat(journal.adaptations).isEmpty();
      assertThat(crew.bonds()).isEqualTo(3);
      assertThat(crew.molecules()).containsExactly(List.of(1, 2, 3, 4));
      assertThat(names(crew, 2))
          .containsExactly("chain", "listen", "follow", "crawl", "feet", "relay");
    }
  }

  @Test
  void aRunLeavesItsOutputsAndTellsTheReconfigurationInItsSummary() {
    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    Summary summary =
        RECONFIGURE.run(
            GaitsTestSupport.settings(Optional.empty(), OptionalLong.of(300), dir),
            new PrintStream(bytes, true, StandardCharsets.UTF_8));
    assertThat(summary.entries())
        .anySatisfy(e -> assertThat(e.value()).contains("atom 2: addSchema detach"))
        .anySatisfy(e -> assertThat(e.value()).contains("removeSchema follow; addSchema pace"))
        .anySatisfy(
            e -> {
              assertThat(e.name()).isEqualTo("molecules at the end");
              assertThat(e.value()).startsWith("[1, 2] at x = ").contains("; [3, 4] at x = ");
            })
        .anySatisfy(
            e -> {
              assertThat(e.name()).isEqualTo("bonds at the end");
              assertThat(e.value()).isEqualTo("2");
            })
        .anySatisfy(
            e -> {
              assertThat(e.name()).isEqualTo("schemas of atom-2");
              assertThat(e.value()).isEqualTo("crawl, relay, pace");
            });
    assertThat(dir.resolve("trace.jsonl")).isNotEmptyFile();
    assertThat(dir.resolve("trajectory.png")).isNotEmptyFile();
    assertThat(dir.resolve("adaptations.png")).isNotEmptyFile();
    assertThat(dir.resolve("molecule-start.png")).isNotEmptyFile();
    assertThat(dir.resolve("molecule-end.png")).isNotEmptyFile();
  }

  @Test
  void atomsOptionIsRefusedSayingWhy() {
    RunSettings settings = GaitsTestSupport.settings(Optional.of(6));
    assertThatThrownBy(() -> RECONFIGURE.scene(settings))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("--atoms");
  }

  private static List<String> names(ReconfigureCrew crew, int id) {
    return crew.robots().get(id - 1).schedule().names();
  }

  private static double x(Simulation sim, int id) {
    return sim.sensors(id).position().x();
  }

  private static LegBinding binding(Simulation sim, int id, Leg leg) {
    return sim.body(id).read(Atom.binding(leg));
  }
}

package org.armgals.examples.robots;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.Journal;
import org.armgals.maam.sim.Simulation;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The battery example on a moving atom, in virtual time, on a battery small enough to run out in a
 * few simulated seconds.
 */
class EnergySaverTest {
  /** Joules: the fast gait drains it in under two simulated seconds. */
  static final double SMALL_BATTERY = 6;

  static final int MAX_CYCLES = 600;

  static final double PERIOD_SECONDS = 0.01;

  record Told(double seconds, String what, String why) {}

  /** A journal that keeps what it is told, stamped with the simulation's time. */
  static final class TestJournal implements Journal {
    final List<Told> adaptations = new ArrayList<>();
    final List<String> notes = new ArrayList<>();
    private final Simulation sim;

    TestJournal(Simulation sim) {
      this.sim = sim;
    }

    @Override
    public void adaptation(int atom, String what, String why) {
      adaptations.add(new Told(sim.timeNanos() / 1e9, what, why));
    }

    @Override
    public void note(int atom, String text) {
      notes.add(text);
    }
  }

  /**
   * How a run went.
   *
   * @param lifetime when the battery was empty, or the end of the run if it lasted that long
   */
  record Outcome(EnergyCrew crew, TestJournal journal, double lifetime) {}

  static RunSettings settings(Path out, OptionalLong cycles) {
    return new RunSettings(
        cycles,
        Optional.empty(),
        Duration.ofMillis(10),
        1,
        Optional.empty(),
        false,
        Optional.empty(),
        out);
  }

  /** Runs {@code example} until its battery is empty, at most {@code maxCycles}. */
  static Outcome untilEmpty(EnergySaver example, int maxCycles) {
    RunSettings settings = settings(Path.of("unused"), OptionalLong.empty());
    try (Simulation sim = Simulation.builder(example.scene(settings)).build()) {
      TestJournal journal = new TestJournal(sim);
      EnergyCrew crew = example.begin(sim, settings, journal);
      for (int i = 0; i < maxCycles && crew.emptyAt().isEmpty(); i++) {
        sim.runCycle();
      }
      assertThat(crew.robot().errors()).isZero();
      return new Outcome(crew, journal, crew.emptyAt().orElse(sim.timeNanos() / 1e9));
    }
  }

  @Test
  void theMetaLevelSwitchesToTheSavingGaitOnceAndTheAtomLastsLonger() {
    Outcome without = untilEmpty(EnergySaver.withoutMetaLevel(SMALL_BATTERY), MAX_CYCLES);
    assertThat(without.crew().emptyAt()).as("the fast gait empties the battery").isPresent();
    // The meta level's run needs to go no further than twice the other's lifetime.
    int twice = (int) Math.ceil(2 * without.lifetime() / PERIOD_SECONDS);
    Outcome with = untilEmpty(new EnergySaver(SMALL_BATTERY, true), twice);

    assertThat(without.crew().gait()).isEqualTo(EnergyGait.FAST);
    assertThat(with.crew().gait()).isEqualTo(EnergyGait.SAVING);
    assertThat(with.lifetime()).isGreaterThan(1.3 * without.lifetime());

    EnergyMeta meta = with.crew().meta();
    assertThat(meta).isNotNull();
    assertThat(meta.switches()).isEqualTo(1);
    assertThat(with.journal().adaptations)
        .singleElement()
        .satisfies(
            told -> {
              assertThat(told.what()).isEqualTo("changeModule stepper {gait=saving}");
              assertThat(told.why()).startsWith("battery at 30%: saving gait");
            });
    double switchedAt = with.journal().adaptations.getFirst().seconds();
    assertThat(switchedAt).isBetween(0.3 * without.lifetime(), 0.9 * without.lifetime());
    // Every state after the threshold meta-event went through the new filter, one per cycle.
    assertThat((double) meta.followed())
        .isCloseTo(with.crew().robot().cycles() - switchedAt / PERIOD_SECONDS, within(2.5));
    assertThat(meta.filter()).isEqualTo(EnergyMeta.FOLLOWING_ENERGY);
    assertThat(meta.savingWatts()).isPositive();
  }

  @Test
  void aRunLeavesItsTraceAndPicturesAndSumsUpTheSwitch(@TempDir Path out) throws Exception {
    ByteArrayOutputStream printed = new ByteArrayOutputStream();
    Summary summary =
        new EnergySaver(SMALL_BATTERY, true)
            .run(
                settings(out, OptionalLong.of(350)),
                new PrintStream(printed, true, StandardCharsets.UTF_8));

    assertThat(summary.entries())
        .contains(
            new Summary.Entry("adaptations", "1"),
            new Summary.Entry("gait", "saving"),
            new Summary.Entry("meta's filter at the end", EnergyMeta.FOLLOWING_ENERGY));
    assertThat(summary.entries())
        .anySatisfy(
            e ->
                assertThat(e.value())
                    .contains("changeModule stepper {gait=saving}")
                    .contains("because battery at 30%"));
    for (String file :
        List.of(
            "trace.jsonl",
            "trajectory.png",
            "energy.png",
            "adaptations.png",
            "molecule-start.png",
            "molecule-end.png")) {
      assertThat(out.resolve(file)).as(file).isNotEmptyFile();
    }
    assertThat(Files.readString(out.resolve("trace.jsonl")))
        .contains("changeModule stepper {gait=saving}");
    assertThat(Files.readString(out.resolve("loop.jsonl")))
        .contains("\"event\":\"filter\"")
        .contains("filter now");
  }

  @Test
  void aRunWithAMetaLevelLeavesThePictureOfItsLoopAndOneWithoutDoesNot(@TempDir Path out) {
    Path with = out.resolve("energy");
    Path without = out.resolve("energy-without-meta");
    PrintStream quiet = new PrintStream(java.io.OutputStream.nullOutputStream());
    new EnergySaver(SMALL_BATTERY, true).run(settings(with, OptionalLong.of(50)), quiet);
    EnergySaver.withoutMetaLevel(SMALL_BATTERY).run(settings(without, OptionalLong.of(50)), quiet);

    assertThat(with.resolve("reflective-loop.png")).isNotEmptyFile();
    assertThat(without.resolve("trajectory.png")).isNotEmptyFile();
    assertThat(without.resolve("reflective-loop.png")).doesNotExist();
  }
}

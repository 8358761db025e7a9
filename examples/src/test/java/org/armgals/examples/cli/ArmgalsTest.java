package org.armgals.examples.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.armgals.examples.run.Example;
import org.armgals.examples.run.RunInterrupted;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.Crew;
import org.armgals.examples.sim.Journal;
import org.armgals.examples.sim.ScriptedExample;
import org.armgals.examples.sim.SimExample;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Simulation;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The command line's contract: what it prints and the status it exits with. */
class ArmgalsTest {

  /** An example that records the settings it was run with. */
  private static final class Recording implements Example {
    final List<RunSettings> runs = new ArrayList<>();

    @Override
    public String name() {
      return "recorder";
    }

    @Override
    public String summary() {
      return "records its settings";
    }

    @Override
    public Summary run(RunSettings settings, PrintStream out) {
      runs.add(settings);
      out.println("running");
      return new Summary(List.of(new Summary.Entry("seed", Long.toString(settings.seed()))));
    }
  }

  private record Result(int status, String out, String err) {}

  private final Recording recording = new Recording();

  private Result run(String... args) {
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    ByteArrayOutputStream err = new ByteArrayOutputStream();
    int status;
    try (PrintStream o = new PrintStream(out, true, StandardCharsets.UTF_8);
        PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8)) {
      status = Armgals.execute(Catalog.of(List.of(recording)), o, e, args);
    }
    return new Result(
        status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
  }

  @Test
  void listPrintsOneLinePerExample() {
    Result r = run("list");
    assertThat(r.status()).isZero();
    assertThat(r.out().lines()).containsExactly("recorder  records its settings");
  }

  @Test
  void standardCatalogListsTheDemo() {
    assertThat(Catalog.standard().find("demo")).isPresent();
  }

  @Test
  void runPassesTheOptionsAndPrintsTheSummary() {
    Result r = run("run", "recorder", "--seed", "42", "--cycles", "7", "--period-ms", "5");
    assertThat(r.status()).isZero();
    assertThat(r.err()).isEmpty();
    assertThat(recording.runs).hasSize(1);
    RunSettings settings = recording.runs.get(0);
    assertThat(settings.seed()).isEqualTo(42);
    assertThat(settings.cycles()).hasValue(7);
    assertThat(settings.period().toMillis()).isEqualTo(5);
    assertThat(r.out()).contains("running").contains("summary of recorder:").contains("seed  42");
  }

  @Test
  void unknownExampleIsOneLineAndStatusTwo() {
    Result r = run("run", "nosuch");
    assertThat(r.status()).isEqualTo(Armgals.USAGE);
    assertThat(r.err().lines())
        .containsExactly("armgals: no example named 'nosuch'; 'armgals list' shows them");
    assertThat(recording.runs).isEmpty();
  }

  @Test
  void badOptionValueIsOneLineAndStatusTwo() {
    Result r = run("run", "recorder", "--cycles", "many");
    assertThat(r.status()).isEqualTo(Armgals.USAGE);
    assertThat(r.err().lines()).hasSize(1);
    assertThat(r.err()).contains("many").contains("armgals run --help");
  }

  @Test
  void unknownOptionIsOneLineAndStatusTwo() {
    Result r = run("run", "recorder", "--fast");
    assertThat(r.status()).isEqualTo(Armgals.USAGE);
    assertThat(r.err().lines()).hasSize(1);
    assertThat(r.err()).contains("--fast");
  }

  @Test
  void outOfRangeSettingIsOneLineAndStatusTwo() {
    Result r = run("run", "recorder", "--cycles", "0");
    assertThat(r.status()).isEqualTo(Armgals.USAGE);
    assertThat(r.err().lines()).containsExactly("armgals: --cycles must be at least 1, was 0");
  }

  @Test
  void cyclesAndSecondsTogetherAreRefused() {
    Result r = run("run", "recorder", "--cycles", "3", "--seconds", "1.5");
    assertThat(r.status()).isEqualTo(Armgals.USAGE);
    assertThat(r.err()).contains("not both");
  }

  @Test
  void aFailingRunIsStatusOne() {
    Example failing =
        new Example() {
          @Override
          public String name() {
            return "failing";
          }

          @Override
          public String summary() {
            return "fails";
          }

          @Override
          public Summary run(RunSettings settings, PrintStream out) {
            throw new IllegalStateException("motor on fire");
          }
        };
    ByteArrayOutputStream err = new ByteArrayOutputStream();
    int status;
    try (PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8)) {
      status =
          Armgals.execute(
              Catalog.of(List.of(failing)), System.out, e, "run", "failing", "--cycles", "1");
    }
    assertThat(status).isEqualTo(Armgals.FAILED);
    assertThat(err.toString(StandardCharsets.UTF_8)).contains("motor on fire");
  }

  @Test
  void anExamplesRefusalOfASettingIsOneLineAndStatusTwo() {
    Example picky =
        new Example() {
          @Override
          public String name() {
            return "picky";
          }

          @Override
          public String summary() {
            return "refuses --atoms";
          }

          @Override
          public Summary run(RunSettings settings, PrintStream out) {
            throw new IllegalArgumentException("'picky' is one atom: --atoms does not apply");
          }
        };
    ByteArrayOutputStream err = new ByteArrayOutputStream();
    int status;
    try (PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8)) {
      status =
          Armgals.execute(
              Catalog.of(List.of(picky)), System.out, e, "run", "picky", "--atoms", "3");
    }
    assertThat(status).isEqualTo(Armgals.USAGE);
    assertThat(err.toString(StandardCharsets.UTF_8).lines())
        .containsExactly("armgals: 'picky' is one atom: --atoms does not apply");
  }

  @Test
  void newWithABadNameIsOneLineAndStatusTwo() {
    Result r = run("new", "My-Bot");
    assertThat(r.status()).isEqualTo(Armgals.USAGE);
    assertThat(r.err().lines()).hasSize(1);
    assertThat(r.err()).startsWith("armgals: 'My-Bot' is not a robot name");
  }

  @Test
  void newIntoAnExistingDirectoryIsOneLineAndStatusTwo(@TempDir Path dir) {
    Result r = run("new", "bot", "--dir", dir.toString());
    assertThat(r.status()).isEqualTo(Armgals.USAGE);
    assertThat(r.err().lines())
        .containsExactly(
            "armgals: " + dir + " already exists; give another name, or another place with --dir");
  }

  @Test
  void newWritesTheSkeletonAndSaysHowToRunIt(@TempDir Path dir) {
    Path target = dir.resolve("bot");
    Result r = run("new", "bot", "--dir", target.toString());
    assertThat(r.status()).as(r.err()).isZero();
    assertThat(r.out())
        .contains("wrote the robot 'bot' in " + target)
        .contains("./mvnw -q verify exec:java");
    assertThat(target.resolve("src/main/java/bot/BotRobot.java")).exists();
  }

  @Test
  void anUnknownCommandIsOneLineAndStatusTwo() {
    Result r = run("fly");
    assertThat(r.status()).isEqualTo(Armgals.USAGE);
    assertThat(r.err().lines()).hasSize(1);
    assertThat(r.err()).contains("fly");
  }

  @Test
  void duplicateNamesInACatalogAreRefused() {
    assertThatThrownBy(() -> Catalog.of(List.of(recording, recording)))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("recorder, recorder");
  }

  @Test
  void everyCommandsHelpExitsZeroWithItsUsageAndTheExitStatuses() {
    for (String command : List.of("list", "run", "replay", "view", "new", "completion")) {
      for (String help : List.of("--help", "-h")) {
        Result r = run(command, help);
        assertThat(r.status()).as("%s %s: %s", command, help, r.err()).isZero();
        assertThat(r.err()).isEmpty();
        assertThat(r.out())
            .as(command)
            .startsWith("Usage: armgals " + command)
            .contains("Exit status:")
            .containsPattern("(?m)^ +0 +done$")
            .containsPattern("(?m)^ +1 +a run failed")
            .containsPattern("(?m)^ +2 +the command line was wrong")
            .containsPattern("(?m)^ +130 +interrupted");
      }
    }
    assertThat(recording.runs).isEmpty();
  }

  @Test
  void aBareArmgalsAndItsHelpCommandListTheCommands() {
    for (Result r : List.of(run(), run("help"), run("--help"))) {
      assertThat(r.status()).isZero();
      assertThat(r.out())
          .startsWith("Usage: armgals")
          .contains("Commands:")
          .containsPattern("(?m)^  list ")
          .containsPattern("(?m)^  run ")
          .containsPattern("(?m)^  replay ")
          .containsPattern("(?m)^  view ")
          .containsPattern("(?m)^  new ")
          .containsPattern("(?m)^  completion ")
          .containsPattern("(?m)^  help ")
          .contains("Exit status:");
    }
  }

  @Test
  void theHelpCommandGivesACommandsUsage() {
    Result r = run("help", "run");
    assertThat(r.status()).isZero();
    assertThat(r.out()).startsWith("Usage: armgals run").contains("--period-ms=<ms>");
  }

  @Test
  void aMistypedOptionOrCommandGetsASuggestion() {
    Result option = run("run", "recorder", "--cycle", "5");
    assertThat(option.status()).isEqualTo(Armgals.USAGE);
    assertThat(option.err().lines())
        .containsExactly(
            "armgals: Unknown options: '--cycle', '5'; did you mean '--cycles'? (try 'armgals run"
                + " --help')");
    Result command = run("lst");
    assertThat(command.status()).isEqualTo(Armgals.USAGE);
    assertThat(command.err()).contains("did you mean 'list'?");
    assertThat(run("rnu", "recorder").err()).contains("did you mean 'run'?");
    assertThat(run("run", "recorder", "--sede", "3").err()).contains("did you mean '--seed'?");
    assertThat(run("fly").err()).doesNotContain("did you mean");
    assertThat(recording.runs).isEmpty();
  }

  @Test
  void editsCountsLettersAddedDroppedChangedAndSwapped() {
    assertThat(Armgals.edits("run", "run")).isZero();
    assertThat(Armgals.edits("rnu", "run")).isEqualTo(1);
    assertThat(Armgals.edits("--cycle", "--cycles")).isEqualTo(1);
    assertThat(Armgals.edits("lst", "list")).isEqualTo(1);
    assertThat(Armgals.edits("replya", "replay")).isEqualTo(1);
    assertThat(Armgals.edits("fly", "list")).isEqualTo(4);
    assertThat(Armgals.edits("", "new")).isEqualTo(3);
  }

  @Test
  void theCompletionScriptCompletesTheCommandsAndTheirOptionsAndIsBash() throws Exception {
    Result r = run("completion");
    assertThat(r.status()).isZero();
    assertThat(r.out())
        .startsWith("#!/usr/bin/env bash")
        .contains("complete -F _complete_armgals")
        .contains("replay")
        .contains("--period-ms")
        .contains("--cycles");
    Process bash = new ProcessBuilder("bash", "-n").redirectErrorStream(true).start();
    try (var in = bash.getOutputStream()) {
      in.write(r.out().getBytes(StandardCharsets.UTF_8));
    }
    String said = new String(bash.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
    assertThat(bash.waitFor()).as(said).isZero();
  }

  @Test
  void valuesThatWouldOverflowOrRoundToNothingAreRefusedNamingTheOption() {
    assertThat(usageError("--seconds", "1e10"))
        .isEqualTo(
            "armgals: --seconds must be at most 9223372036 (292 years of simulated time, the most a"
                + " run can count in nanoseconds), was 10000000000");
    assertThat(usageError("--seconds", "1e-12"))
        .isEqualTo(
            "armgals: --seconds must be at least a nanosecond (0.000000001), was 0.000000000001");
    assertThat(usageError("--seconds", "NaN"))
        .isEqualTo("armgals: --seconds must be positive and finite, was NaN");
    assertThat(usageError("--seconds", "-2"))
        .isEqualTo("armgals: --seconds must be positive and finite, was -2");
    assertThat(usageError("--period-ms", "0"))
        .isEqualTo("armgals: --period-ms must be positive, was 0");
    assertThat(usageError("--period-ms", "9223372036854775807"))
        .isEqualTo(
            "armgals: --period-ms must be at most 3600000 (an hour), was 9223372036854775807");
    assertThat(usageError("--atoms", "0")).isEqualTo("armgals: --atoms must be at least 1, was 0");
    assertThat(RunCommand.simulated(RunCommand.MAX_SECONDS).toNanos())
        .isEqualTo(RunCommand.MAX_SECONDS * 1_000_000_000L);
    assertThat(recording.runs).isEmpty();
  }

  private String usageError(String option, String value) {
    Result r = run("run", "recorder", option, value);
    assertThat(r.status()).as(r.err()).isEqualTo(Armgals.USAGE);
    assertThat(r.err().lines()).hasSize(1);
    return r.err().strip();
  }

  /** The settings {@code args} give a simulated example that records them instead of running. */
  private static Result runSimulated(List<RunSettings> runs, boolean usesBroker, String... args) {
    ScriptedExample scripted = new ScriptedExample("simulated", usesBroker);
    SimExample simulated =
        new SimExample() {
          @Override
          public String name() {
            return scripted.name();
          }

          @Override
          public String summary() {
            return scripted.summary();
          }

          @Override
          public Scene scene(RunSettings settings) {
            return scripted.scene(settings);
          }

          @Override
          public Duration defaultDuration() {
            return scripted.defaultDuration();
          }

          @Override
          public boolean usesBroker() {
            return scripted.usesBroker();
          }

          @Override
          public Crew start(Simulation sim, RunSettings settings, Journal journal) {
            return scripted.start(sim, settings, journal);
          }

          @Override
          public Summary run(RunSettings settings, PrintStream out) {
            runs.add(settings);
            return new Summary(List.of());
          }
        };
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    ByteArrayOutputStream err = new ByteArrayOutputStream();
    int status;
    try (PrintStream o = new PrintStream(out, true, StandardCharsets.UTF_8);
        PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8)) {
      status = Armgals.execute(Catalog.of(List.of(simulated)), o, e, args);
    }
    return new Result(
        status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
  }

  @Test
  void aRunPacedToRealTimeIsWarmedUpFiveSecondsUnlessToldOtherwiseAndOnlyThen() {
    List<RunSettings> runs = new ArrayList<>();

    runSimulated(runs, false, "run", "simulated", "--realtime");
    runSimulated(runs, false, "run", "simulated");
    runSimulated(runs, false, "run", "simulated", "--realtime", "--warmup-seconds", "1.5");
    runSimulated(runs, false, "run", "simulated", "--realtime", "--warmup-seconds", "0");
    runSimulated(runs, true, "run", "simulated", "--realtime");
    run("run", "recorder", "--realtime");

    assertThat(runs)
        .extracting(RunSettings::warmup)
        .containsExactly(
            RunSettings.DEFAULT_WARMUP,
            Duration.ZERO,
            Duration.ofMillis(1500),
            Duration.ZERO,
            Duration.ZERO);
    assertThat(RunSettings.DEFAULT_WARMUP).isEqualTo(Duration.ofSeconds(5));
    assertThat(recording.runs).extracting(RunSettings::warmup).containsExactly(Duration.ZERO);
  }

  @Test
  void aWarmUpThatCannotApplyIsRefusedInOneLineNamingWhy() {
    List<RunSettings> runs = new ArrayList<>();

    Result virtual = runSimulated(runs, false, "run", "simulated", "--warmup-seconds", "2");
    Result negative =
        runSimulated(runs, false, "run", "simulated", "--realtime", "--warmup-seconds", "-1");
    Result elsewhere =
        runSimulated(runs, true, "run", "simulated", "--realtime", "--warmup-seconds", "2");

    assertThat(List.of(virtual, negative, elsewhere))
        .allSatisfy(r -> assertThat(r.status()).isEqualTo(Armgals.USAGE));
    assertThat(virtual.err().strip())
        .isEqualTo(
            "armgals: --warmup-seconds applies to a run paced to real time: add --realtime or"
                + " --live");
    assertThat(negative.err().strip())
        .isEqualTo("armgals: --warmup-seconds must be 0 or more, was -1");
    assertThat(elsewhere.err().strip())
        .isEqualTo(
            "armgals: --warmup-seconds does not apply to 'simulated': its robots run in JVMs of"
                + " their own, which a warm-up in this one would not warm");
    assertThat(runs).isEmpty();
  }

  @Test
  void anOutputDirectoryThatCannotBeMadeIsOneLineWithTheSystemsReason(@TempDir Path dir)
      throws Exception {
    Path file = Files.writeString(dir.resolve("a-file"), "not a directory\n");
    Path out = file.resolve("run");
    ByteArrayOutputStream err = new ByteArrayOutputStream();
    int status;
    try (PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8)) {
      status =
          Armgals.execute(
              Catalog.of(List.of(new ScriptedExample())),
              new PrintStream(OutputStream.nullOutputStream()),
              e,
              "run",
              "scripted",
              "--cycles",
              "2",
              "--out",
              out.toString());
    }
    assertThat(status).isEqualTo(Armgals.FAILED);
    assertThat(err.toString(StandardCharsets.UTF_8).lines())
        .containsExactly(
            "armgals: cannot create the output directory " + out + ": Not a directory");
  }

  @Test
  void theReasonOfAnIoErrorIsTheSystemsEvenWhenJavaLeavesItOut() {
    assertThat(Armgals.reason(new AccessDeniedException("/x"))).isEqualTo("Permission denied");
    assertThat(Armgals.reason(new NoSuchFileException("/x")))
        .isEqualTo("No such file or directory");
    assertThat(Armgals.reason(new FileSystemException("/x", null, "No space left on device")))
        .isEqualTo("No space left on device");
  }

  @Test
  void anInterruptedRunIsStatus130AndNothingMoreIsPrinted() {
    Example interrupted =
        new Example() {
          @Override
          public String name() {
            return "stopped";
          }

          @Override
          public String summary() {
            return "is interrupted";
          }

          @Override
          public Summary run(RunSettings settings, PrintStream out) {
            out.println("stopped: interrupted after 3 cycles");
            throw new RunInterrupted("stopped after 3 cycles");
          }
        };
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    ByteArrayOutputStream err = new ByteArrayOutputStream();
    int status;
    try (PrintStream o = new PrintStream(out, true, StandardCharsets.UTF_8);
        PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8)) {
      status = Armgals.execute(Catalog.of(List.of(interrupted)), o, e, "run", "stopped");
    }
    assertThat(status).isEqualTo(Armgals.INTERRUPTED).isEqualTo(130);
    assertThat(out.toString(StandardCharsets.UTF_8))
        .isEqualTo("stopped: interrupted after 3 cycles" + System.lineSeparator());
    assertThat(err.toString(StandardCharsets.UTF_8)).isEmpty();
  }
}

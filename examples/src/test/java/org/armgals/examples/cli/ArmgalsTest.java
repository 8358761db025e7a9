package org.armgals.examples.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
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
    assertThat(r.err().lines()).containsExactly("armgals: --cycles must be at least 1, not 0");
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
        .contains("mvn -q compile exec:java");
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
}

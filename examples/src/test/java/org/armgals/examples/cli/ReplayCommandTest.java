package org.armgals.examples.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.armgals.examples.sim.ScriptedExample;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code armgals replay}: a fresh run reproduces; a changed trace differs; bad input is status 2.
 */
class ReplayCommandTest {
  private static final Catalog CATALOG =
      Catalog.of(List.of(new ScriptedExample(), new DemoExample()));

  /** One run for all the tests, which each work on a copy of its trace. */
  @TempDir static Path runs;

  private static Path original;

  @TempDir Path dir;

  private Path trace;

  private record Result(int status, String out, String err) {}

  private static Result armgals(Catalog catalog, String... args) {
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    ByteArrayOutputStream err = new ByteArrayOutputStream();
    int status;
    try (PrintStream o = new PrintStream(out, true, StandardCharsets.UTF_8);
        PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8)) {
      status = Armgals.execute(catalog, o, e, args);
    }
    return new Result(
        status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
  }

  private static Result armgals(String... args) {
    return armgals(CATALOG, args);
  }

  @BeforeAll
  static void aRun() {
    Path out = runs.resolve("run");
    Result run =
        armgals(
            "run",
            "scripted",
            "--cycles",
            "12",
            "--seed",
            "5",
            "--atoms",
            "2",
            "--out",
            out.toString());
    assertThat(run.status()).as(run.err()).isZero();
    original = out.resolve("trace.jsonl");
  }

  @BeforeEach
  void aCopy() throws IOException {
    trace = Files.copy(original, dir.resolve("trace.jsonl"));
  }

  @Test
  void aFreshRunIsReproducedExactly() {
    Result r = armgals("replay", trace.toString());

    assertThat(r.status()).as(r.err()).isZero();
    assertThat(r.out().lines().toList().get(0))
        .isEqualTo("replaying " + trace + ": 'scripted', 12 cycles of 10 ms, seed 5");
    assertThat(r.out().lines().toList().get(1))
        .matches("reproduced exactly: 12 cycles, trace sha-256 [0-9a-f]{64}");
  }

  @Test
  void aRunsOutputDirectoryStandsForItsTrace() throws IOException {
    Result r = armgals("replay", dir.toString());

    assertThat(r.status()).as(r.err()).isZero();
    assertThat(r.out().lines().toList().get(0)).startsWith("replaying " + trace + ": 'scripted'");
    assertThat(r.out()).contains("reproduced exactly: 12 cycles");

    Path empty = Files.createDirectory(dir.resolve("empty"));
    assertThat(oneLineError(armgals("replay", empty.toString())))
        .contains("no trace in " + empty)
        .contains("output directory of 'armgals run'");
  }

  @Test
  void aChangedTraceDiffersFromTheCycleChanged() throws IOException {
    List<String> lines = new ArrayList<>(Files.readAllLines(trace, StandardCharsets.UTF_8));
    // the line of cycle 7 (the header is line 0): nudge atom 2's energy
    String line = lines.get(8);
    int energy = line.indexOf("\"energy\":", line.indexOf("{\"id\":2"));
    lines.set(8, line.substring(0, energy) + "\"energy\":1" + line.substring(energy + 9));
    Files.write(trace, lines, StandardCharsets.UTF_8);

    Result r = armgals("replay", trace.toString());

    assertThat(r.status()).isEqualTo(Armgals.FAILED);
    String verdict = r.out().lines().toList().get(1);
    assertThat(verdict)
        .startsWith("differs from cycle 7: atom 2, field 'energy': trace has \"energy\":1");
  }

  @Test
  void aTruncatedTraceDiffersWhereItEnds() throws IOException {
    List<String> lines = Files.readAllLines(trace, StandardCharsets.UTF_8);
    Files.write(trace, lines.subList(0, 1 + 10), StandardCharsets.UTF_8);

    Result r = armgals("replay", trace.toString());

    assertThat(r.status()).isEqualTo(Armgals.FAILED);
    assertThat(r.out()).contains("differs from cycle 10: the trace ends before it");
  }

  @Test
  void badInputsAreOneLineAndStatusTwo() throws IOException {
    Path missing = dir.resolve("nothing.jsonl");
    Path notATrace = Files.writeString(dir.resolve("notes.txt"), "hello\n");
    Path empty = Files.writeString(dir.resolve("empty.jsonl"), "");
    String header = Files.readAllLines(trace, StandardCharsets.UTF_8).get(0);
    Path later =
        Files.writeString(
            dir.resolve("v2.jsonl"), header.replace("\"version\":1", "\"version\":2"));
    Path bare =
        Files.writeString(
            dir.resolve("bare.jsonl"),
            header.replaceAll("\"attributes\":\\{[^}]*}", "\"attributes\":{}"));

    assertThat(oneLineError(armgals("replay", missing.toString())))
        .isEqualTo("armgals: no trace at " + missing + "; 'armgals run' leaves one in its --out");
    assertThat(oneLineError(armgals("replay", notATrace.toString())))
        .contains("not an armgals trace");
    assertThat(oneLineError(armgals("replay", empty.toString()))).contains("not an armgals trace");
    assertThat(oneLineError(armgals("replay", later.toString())))
        .contains("a trace of version 2: this armgals reads version 1");
    assertThat(oneLineError(armgals("replay", bare.toString())))
        .contains("the trace names no example");
    assertThat(
            oneLineError(
                armgals(Catalog.of(List.of(new DemoExample())), "replay", trace.toString())))
        .contains("a trace of example 'scripted', which this armgals does not have");
    assertThat(oneLineError(armgals("replay"))).contains("<trace>");
  }

  private static String oneLineError(Result r) {
    assertThat(r.status()).as(r.err()).isEqualTo(Armgals.USAGE);
    assertThat(r.err().lines()).as(r.err()).hasSize(1);
    return r.err().strip();
  }
}

package org.armgals.examples.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.armgals.examples.sim.ScriptedMain;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Ctrl-C in a run, for real: a JVM running {@code armgals run} paced to real time gets SIGINT once
 * it has shown progress, says it was interrupted, keeps its trace marked incomplete, exits 130, and
 * {@code replay} reproduces the trace as far as it goes.
 */
class CtrlCTest {
  @TempDir Path dir;

  @Test
  void aRunGivenSigintSaysSoKeepsItsTraceMarkedIncompleteAndExits130() throws Exception {
    // A process started in the background by a shell without job control ignores SIGINT, and so
    // does every process it starts: the JVM then installs no handler, and a run cannot be stopped.
    assertThat(sigintIgnored())
        .as(
            "SIGINT is ignored by this test's JVM (inherited from the shell that started the build"
                + " in the background); start the build from a shell with job control (set -m)")
        .isFalse();
    Path out = dir.resolve("run");
    Process run =
        new ProcessBuilder(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp",
                System.getProperty("java.class.path"),
                ScriptedMain.class.getName(),
                "run",
                "scripted",
                "--realtime",
                "--seconds",
                "20",
                "--out",
                out.toString())
            .redirectErrorStream(true)
            .start();
    List<String> lines = new ArrayList<>();
    try (BufferedReader said =
        new BufferedReader(new InputStreamReader(run.getInputStream(), StandardCharsets.UTF_8))) {
      // progress is shown at each tenth of the run: 2 s of real time in
      for (String line = said.readLine(); line != null; line = said.readLine()) {
        lines.add(line);
        if (line.startsWith(" 10%")) {
          interrupt(run);
        }
      }
    } finally {
      if (!run.waitFor(60, TimeUnit.SECONDS)) {
        run.destroyForcibly();
      }
    }

    assertThat(run.exitValue()).as(String.join("\n", lines)).isEqualTo(Armgals.INTERRUPTED);
    assertThat(lines.get(lines.size() - 1))
        .matches(
            "armgals scripted: interrupted after \\d+ of 2000 cycles \\([0-9.]+ s simulated\\); the"
                + " trace up to there \\(marked incomplete\\) and the pictures are in "
                + java.util.regex.Pattern.quote(out.toString()));
    List<String> trace = Files.readAllLines(out.resolve("trace.jsonl"), StandardCharsets.UTF_8);
    assertThat(trace.get(trace.size() - 1))
        .matches(
            "\\{\"type\":\"incomplete\",\"cycles\":\\d+,\"of\":2000,\"reason\":\"interrupted\"}");
    assertThat(out.resolve("trajectory.png")).isNotEmptyFile();

    ByteArrayOutputStreamResult replay = replay(out.resolve("trace.jsonl"));
    assertThat(replay.status()).as(replay.out()).isZero();
    assertThat(replay.out())
        .contains("reproduced exactly up to where the trace stops (the run was interrupted): ");
  }

  private static void interrupt(Process run) throws IOException, InterruptedException {
    Process kill = new ProcessBuilder("kill", "-INT", Long.toString(run.pid())).start();
    assertThat(kill.waitFor()).isZero();
  }

  /** Whether this process ignores SIGINT, from its mask of ignored signals in /proc (Linux). */
  private static boolean sigintIgnored() throws IOException {
    Path status = Path.of("/proc/self/status");
    if (!Files.isReadable(status)) {
      return false;
    }
    for (String line : Files.readAllLines(status, StandardCharsets.US_ASCII)) {
      if (line.startsWith("SigIgn:")) {
        long ignored = Long.parseUnsignedLong(line.substring("SigIgn:".length()).trim(), 16);
        return (ignored & (1L << (2 - 1))) != 0; // bit n - 1 stands for signal n; SIGINT is 2
      }
    }
    return false;
  }

  private record ByteArrayOutputStreamResult(int status, String out) {}

  private static ByteArrayOutputStreamResult replay(Path trace) {
    java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
    int status;
    try (java.io.PrintStream out = new java.io.PrintStream(bytes, true, StandardCharsets.UTF_8)) {
      status =
          Armgals.execute(
              Catalog.of(List.of(new org.armgals.examples.sim.ScriptedExample())),
              out,
              out,
              "replay",
              trace.toString());
    }
    return new ByteArrayOutputStreamResult(status, bytes.toString(StandardCharsets.UTF_8));
  }
}

package org.armgals.examples.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.StringWriter;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.concurrent.atomic.AtomicLong;
import javax.imageio.ImageIO;
import org.armgals.examples.cli.RunSettings;
import org.armgals.examples.cli.Summary;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What a run of a simulated example leaves: its trace, its pictures, its summary and progress. */
class SimRunTest {
  private static final Duration PERIOD = Duration.ofMillis(10);

  @TempDir Path dir;

  private final ScriptedExample example = new ScriptedExample();

  private RunSettings settings(OptionalLong cycles, Optional<Duration> simulated) {
    return new RunSettings(
        cycles, simulated, PERIOD, 7, Optional.empty(), false, Optional.empty(), dir);
  }

  private RunSettings cycles(long n) {
    return settings(OptionalLong.of(n), Optional.empty());
  }

  private static RunSettings withAtoms(RunSettings s, int atoms) {
    return new RunSettings(
        s.cycles(),
        s.simulated(),
        s.period(),
        s.seed(),
        Optional.of(atoms),
        s.realTime(),
        s.broker(),
        s.out());
  }

  private record Run(Summary summary, String out) {
    Map<String, String> entries() {
      Map<String, String> map = new LinkedHashMap<>();
      summary.entries().forEach(e -> map.put(e.name(), e.value()));
      return map;
    }
  }

  private Run run(RunSettings settings, boolean terminal, AtomicLong clock) {
    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    Summary summary;
    try (PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8)) {
      summary = SimRun.run(example, settings, out, terminal, clock::get);
    }
    return new Run(summary, bytes.toString(StandardCharsets.UTF_8));
  }

  private static String header(Path trace) throws IOException {
    return Files.readAllLines(trace, StandardCharsets.UTF_8).get(0);
  }

  @Test
  void aRunLeavesItsTraceWithTheOptionsInItsHeaderAndItsPictures() throws IOException {
    run(withAtoms(cycles(20), 2), false, new AtomicLong());

    Path trace = dir.resolve(SimRun.TRACE);
    assertThat(header(trace))
        .contains("\"seed\":7")
        .contains(
            "\"attributes\":{\"example\":\"scripted\",\"cycles\":\"20\","
                + "\"periodNanos\":\"10000000\",\"atoms\":\"2\"}");
    assertThat(Files.readAllLines(trace, StandardCharsets.UTF_8)).hasSize(1 + 20);
    assertThat(Files.readString(trace, StandardCharsets.UTF_8))
        .contains("adaptation: switched gait, because scripted at cycle 5")
        .contains("\"text\":\"a note\"");
    for (String png :
        List.of(
            Outputs.TRAJECTORY, Outputs.ENERGY, Outputs.ADAPTATIONS, Outputs.START, Outputs.END)) {
      BufferedImage image = ImageIO.read(dir.resolve(png).toFile());
      assertThat(image).as(png).isNotNull();
      assertThat(image.getWidth()).as(png).isPositive();
    }
  }

  @Test
  void theAtomsAttributeIsLeftOutWhenNotGiven() throws IOException {
    run(cycles(3), false, new AtomicLong());

    assertThat(header(dir.resolve(SimRun.TRACE)))
        .contains(
            "\"attributes\":{\"example\":\"scripted\",\"cycles\":\"3\","
                + "\"periodNanos\":\"10000000\"}");
  }

  @Test
  void theSummaryHasTheCommonFiguresTheAdaptationsWithWhyAndTheCrewsOwn() {
    Map<String, String> entries = run(cycles(20), false, new AtomicLong()).entries();

    assertThat(entries.keySet())
        .containsSubsequence(
            "simulated time",
            "distance",
            "speed",
            "energy used",
            "adaptations",
            "missed cycles",
            "gait",
            "outputs");
    assertThat(entries.get("simulated time")).isEqualTo("0.20 s");
    assertThat(entries.get("distance")).matches("\\d+\\.\\d{3} m");
    assertThat(entries.get("speed")).matches("\\d+\\.\\d{3} atom diameters/s \\(0\\.22 m each\\)");
    assertThat(entries.get("energy used")).matches("\\d+\\.\\d{2} J");
    assertThat(Double.parseDouble(entries.get("energy used").replace(" J", ""))).isPositive();
    assertThat(entries.get("adaptations")).isEqualTo("1");
    // told at the start of cycle 5, at 50 ms of simulated time
    assertThat(entries.get("  at 0.05 s"))
        .isEqualTo("atom 1: switched gait, because scripted at cycle 5");
    assertThat(entries.get("missed cycles")).isEqualTo(Long.toString(ScriptedExample.MISSED));
    assertThat(entries.get("gait")).isEqualTo("scripted");
    assertThat(entries.get("outputs")).isEqualTo(dir.toString());
  }

  @Test
  void cyclesComeFromTheCyclesTheSecondsOrTheDefaultDurationRoundedUp() {
    assertThat(SimRun.cycles(example, cycles(7))).isEqualTo(7);
    assertThat(
            SimRun.cycles(
                example, settings(OptionalLong.empty(), Optional.of(Duration.ofMillis(105)))))
        .isEqualTo(11);
    assertThat(
            SimRun.cycles(
                example, settings(OptionalLong.empty(), Optional.of(Duration.ofMillis(100)))))
        .isEqualTo(10);
    // 250 ms by default, in periods of 10 ms
    assertThat(SimRun.cycles(example, settings(OptionalLong.empty(), Optional.empty())))
        .isEqualTo(25);
    RunSettings slow =
        new RunSettings(
            OptionalLong.empty(),
            Optional.empty(),
            Duration.ofMillis(30),
            1,
            Optional.empty(),
            false,
            Optional.empty(),
            dir);
    assertThat(SimRun.cycles(example, slow)).isEqualTo(9); // 8.33 rounded up
  }

  @Test
  void aBrokerIsRefusedForAnExampleThatUsesNoneNamingIt() {
    Path out = dir.resolve("not-made");
    RunSettings broker =
        new RunSettings(
            OptionalLong.of(3),
            Optional.empty(),
            PERIOD,
            1,
            Optional.empty(),
            false,
            Optional.of(URI.create("tcp://localhost:61616")),
            out);

    assertThatThrownBy(() -> run(broker, false, new AtomicLong()))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'scripted'")
        .hasMessageContaining("--broker");
    assertThatThrownBy(() -> SimRun.traceOnly(example, broker, new StringWriter()))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'scripted'");
    assertThat(out).doesNotExist();
  }

  @Test
  void anOptionThatDoesNotApplyIsRefusedBeforeAnythingIsWritten() {
    assertThatThrownBy(() -> run(withAtoms(cycles(3), 9), false, new AtomicLong()))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("--atoms 9");
    assertThat(dir.resolve(SimRun.TRACE)).doesNotExist();
  }

  @Test
  void aRunTracedOnlyWritesTheSameTraceAsAFullRun() throws IOException {
    run(cycles(12), false, new AtomicLong());
    StringWriter again = new StringWriter();

    SimRun.traceOnly(example, cycles(12), again);

    assertThat(again.toString())
        .isEqualTo(Files.readString(dir.resolve(SimRun.TRACE), StandardCharsets.UTF_8));
  }

  @Test
  void offATerminalTheProgressIsAPlainLineAtEachTenth() {
    String out = run(cycles(20), false, new AtomicLong()).out();

    List<String> progress = out.lines().filter(l -> l.contains("% ")).toList();
    assertThat(progress).hasSize(10);
    assertThat(progress.get(0)).startsWith(" 10%  simulated 0.02 s");
    assertThat(progress.get(9)).startsWith("100%  simulated 0.20 s");
    assertThat(out).doesNotContain("\r").doesNotContain("[#");
  }

  @Test
  void onATerminalTheProgressIsABarRedrawnInPlace() {
    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    AtomicLong now = new AtomicLong();
    try (PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8)) {
      Progress progress = new Progress(out, true, 10, now::get);
      for (int cycle = 1; cycle <= 10; cycle++) {
        now.addAndGet(100_000_000L); // 100 ms of real time per cycle of 50 ms simulated
        progress.update(cycle, cycle * 50_000_000L);
      }
    }
    String out = bytes.toString(StandardCharsets.UTF_8);

    // redrawn every 200 ms of real time: cycles 2, 4, 6, 8, 10
    assertThat(out.split("\r", -1)).hasSize(1 + 5);
    assertThat(out)
        .startsWith("\r[######                        ]  20%  simulated 0.10 s  10 cycles/s  0.5×")
        .endsWith(
            "\r[##############################] 100%  simulated 0.50 s  10 cycles/s"
                + "  0.5× real time"
                + System.lineSeparator());
  }
}

package org.armgals.examples.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
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
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.armgals.examples.run.RunInterrupted;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.maam.sim.Scene;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;
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
                + "\"periodNanos\":\"10000000\",\"legs\":\"kinematic\",\"atoms\":\"2\"}");
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
  void aRunLeavesExactlyTheFilesTheUserGuideListsAndAnSvgBesideEachPng() throws IOException {
    run(cycles(20), false, new AtomicLong());

    Path root = Path.of("").toAbsolutePath();
    while (!Files.isRegularFile(root.resolve("docs/user-guide.md"))) {
      root = root.getParent();
    }
    String guide = Files.readString(root.resolve("docs/user-guide.md"), StandardCharsets.UTF_8);
    String outputs = guide.substring(guide.indexOf("## Read the outputs"));
    int start = outputs.indexOf("| file |");
    java.util.Set<String> listed = new java.util.TreeSet<>();
    for (String row : outputs.substring(start, outputs.indexOf("\n\n", start)).split("\n")) {
      if (row.split("\\|")[2].strip().startsWith("with ")) {
        continue; // a file of runs with a meta level, or with --meta remote
      }
      java.util.regex.Matcher name =
          java.util.regex.Pattern.compile("`([^`]+)`").matcher(row.split("\\|")[1]);
      while (name.find()) {
        listed.add(name.group(1));
      }
    }
    try (Stream<Path> files = Files.list(dir)) {
      assertThat(files.map(p -> p.getFileName().toString()))
          .as("the files of a run without a meta level, as docs/user-guide.md lists them")
          .containsExactlyInAnyOrderElementsOf(listed)
          .contains(Outputs.svg(Outputs.TRAJECTORY), Outputs.svg(Outputs.END));
    }
  }

  @Test
  void theAtomsAttributeIsLeftOutWhenNotGiven() throws IOException {
    run(cycles(3), false, new AtomicLong());

    assertThat(header(dir.resolve(SimRun.TRACE)))
        .contains(
            "\"attributes\":{\"example\":\"scripted\",\"cycles\":\"3\","
                + "\"periodNanos\":\"10000000\",\"legs\":\"kinematic\"}");
  }

  @Test
  void theSummaryHasTheCommonFiguresTheAdaptationsWithWhyAndTheCrewsOwn() {
    Map<String, String> entries = run(cycles(20), false, new AtomicLong()).entries();

    assertThat(entries.keySet())
        .containsSubsequence(
            "simulated time",
            "displacement",
            "path length",
            "speed",
            "energy used",
            "adaptations",
            "missed cycles",
            "gait",
            "outputs");
    assertThat(entries.get("simulated time")).isEqualTo("0.20 s");
    assertThat(entries.get("displacement")).matches("\\d+\\.\\d{3} m");
    assertThat(entries.get("path length")).matches("\\d+\\.\\d{3} m");
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

  /** How a test's example starts its crew. */
  private interface Start {
    Crew start(Simulation sim, RunSettings settings, Journal journal);
  }

  /** The scripted example, its crew started by {@code start}. */
  private SimExample startedBy(Start start) {
    return new SimExample() {
      @Override
      public String name() {
        return example.name();
      }

      @Override
      public String summary() {
        return example.summary();
      }

      @Override
      public Scene scene(RunSettings settings) {
        return example.scene(settings);
      }

      @Override
      public Duration defaultDuration() {
        return example.defaultDuration();
      }

      @Override
      public Crew start(Simulation sim, RunSettings settings, Journal journal) {
        return start.start(sim, settings, journal);
      }
    };
  }

  /** {@code example} run for {@code cycles}, paced to real time, the run's time read from now. */
  private Summary pacedToRealTime(SimExample example, long cycles, AtomicLong now) {
    RunSettings settings =
        new RunSettings(
            OptionalLong.of(cycles),
            Optional.empty(),
            PERIOD,
            7,
            Optional.empty(),
            true,
            Optional.empty(),
            dir);
    try (PrintStream out =
        new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8)) {
      return SimRun.run(example, settings, out, false, now::get);
    }
  }

  @Test
  void pacedToRealTimeTheCyclesAreMissedFromTheFirstCycleOnNotFromTheCrewsStart() {
    AtomicLong now = new AtomicLong();
    SimExample slowToStart =
        startedBy(
            (sim, settings, journal) -> {
              now.addAndGet(Duration.ofSeconds(2).toNanos()); // a meta level's JVM starting, say
              return example.start(sim, settings, journal);
            });

    Summary summary = pacedToRealTime(slowToStart, 5, now);

    // No real time passes on the run's clock once the crew has started: only the crew's own.
    assertThat(summary.entries())
        .contains(new Summary.Entry("missed cycles", Long.toString(ScriptedExample.MISSED)));
  }

  @Test
  void pacedToRealTimeAFirstCycleSlowedByWarmingUpMissesNothingLaterWhileALateCycleStillCounts() {
    AtomicLong now = new AtomicLong();
    long period = PERIOD.toNanos();
    SimExample warmingUp =
        startedBy(
            (sim, settings, journal) -> {
              sim.setController(
                  sim.atomIds().get(0),
                  (body, cycle) -> {
                    now.addAndGet(period); // each cycle takes its period of real time...
                    if (cycle == 0) {
                      now.addAndGet(Duration.ofSeconds(1).toNanos()); // ...the first, warming up
                    }
                    if (cycle == 3) {
                      now.addAndGet(3 * period); // ...and cycle 3 ends late: it and those after
                    }
                  });
              return new Crew() {};
            });

    Summary summary = pacedToRealTime(warmingUp, 6, now);

    assertThat(summary.entries()).contains(new Summary.Entry("missed cycles", "3"));
  }

  /** {@code cycles} of {@code example} paced to real time into {@code out}, warmed up or not. */
  private Run paced(SimExample example, long cycles, Path out, Duration warmup) {
    RunSettings settings =
        new RunSettings(
            OptionalLong.of(cycles),
            Optional.empty(),
            PERIOD,
            7,
            Optional.empty(),
            true,
            Optional.empty(),
            out,
            RunSettings.MetaPlace.REMOTE,
            warmup);
    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    Summary summary;
    try (PrintStream print = new PrintStream(bytes, true, StandardCharsets.UTF_8)) {
      summary = SimRun.run(example, settings, print, false, new AtomicLong()::get);
    }
    return new Run(summary, bytes.toString(StandardCharsets.UTF_8));
  }

  @Test
  void aWarmUpRunsTheSameRobotsFirstInVirtualTimeWithTheirMetaHereAndLeavesNoTraceOfIt()
      throws IOException {
    List<RunSettings> starts = new java.util.ArrayList<>();
    SimExample recorded =
        startedBy(
            (sim, settings, journal) -> {
              starts.add(settings);
              return example.start(sim, settings, journal);
            });
    Path plain = dir.resolve("plain");
    Path warmed = dir.resolve("warmed");
    paced(recorded, 6, plain, Duration.ZERO);
    starts.clear();

    Run run = paced(recorded, 6, warmed, Duration.ofMillis(30));

    assertThat(starts).hasSize(2);
    RunSettings warmUp = starts.get(0);
    assertThat(warmUp.realTime()).isFalse();
    assertThat(warmUp.meta()).isEqualTo(RunSettings.MetaPlace.LOCAL);
    assertThat(warmUp.cycles()).hasValue(3);
    assertThat(warmUp.seed()).isEqualTo(7);
    assertThat(warmUp.warmup()).isZero();
    assertThat(warmUp.out()).doesNotExist();
    RunSettings real = starts.get(1);
    assertThat(real.realTime()).isTrue();
    assertThat(real.meta()).isEqualTo(RunSettings.MetaPlace.REMOTE);
    assertThat(real.cycles()).hasValue(6);
    assertThat(files(warmed).keySet()).isEqualTo(files(plain).keySet());
    assertThat(Files.readString(warmed.resolve(SimRun.TRACE), StandardCharsets.UTF_8))
        .isEqualTo(Files.readString(plain.resolve(SimRun.TRACE), StandardCharsets.UTF_8));
    assertThat(run.out()).contains("warmed up: 0.03 s simulated in ");
    assertThat(run.entries())
        .containsEntry("warm-up", "0.03 s simulated before the run, in virtual time, thrown away");
  }

  @Test
  void aWarmUpRunsItsLengthRoundedUpToAWholeCycle() {
    assertThat(SimRun.warmUpCycles(Duration.ofMillis(30), PERIOD)).isEqualTo(3);
    assertThat(SimRun.warmUpCycles(Duration.ofMillis(25), PERIOD)).isEqualTo(3);
    assertThat(SimRun.warmUpCycles(Duration.ofNanos(1), PERIOD)).isEqualTo(1);
    assertThat(SimRun.warmUpCycles(Duration.ZERO, PERIOD)).isZero();
  }

  @Test
  void aWarmUpOfRobotsInJvmsOfTheirOwnIsRefusedNamingTheExampleAndTheOption() {
    Path out = dir.resolve("not-made");

    assertThatThrownBy(
            () -> paced(new ScriptedExample("spread", true), 3, out, Duration.ofSeconds(1)))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("'spread'")
        .hasMessageContaining("--warmup-seconds");
    assertThat(out).doesNotExist();
  }

  @Test
  void aWarmUpIsRefusedInVirtualTimeAndWhenNegative() {
    RunSettings virtual = cycles(3);

    assertThatThrownBy(() -> virtual.withWarmup(Duration.ofSeconds(1)))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("--warmup-seconds applies to a run paced to real time")
        .hasMessageContaining("PT1S");
    assertThatThrownBy(() -> virtual.pacedToRealTime().withWarmup(Duration.ofSeconds(-1)))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("--warmup-seconds must not be negative")
        .hasMessageContaining("PT-1S");
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

  /** A scripted example whose crew cannot start, as a distributed one with no broker. */
  private static final class FailingAtStart implements SimExample {
    private final ScriptedExample scripted = new ScriptedExample();

    @Override
    public String name() {
      return scripted.name();
    }

    @Override
    public String summary() {
      return "cannot start";
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
    public Crew start(Simulation sim, RunSettings settings, Journal journal) {
      throw new IllegalStateException("could not reach the broker");
    }
  }

  /**
   * A scripted tripod whose controller asks {@code interruption} to stop the run during cycle
   * {@code at}, as Ctrl-C would.
   */
  private static final class InterruptedAt implements SimExample {
    private final ScriptedExample scripted = new ScriptedExample();
    private final Interruption interruption;
    private final long at;

    InterruptedAt(Interruption interruption, long at) {
      this.interruption = interruption;
      this.at = at;
    }

    @Override
    public String name() {
      return scripted.name();
    }

    @Override
    public String summary() {
      return "interrupted";
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
    public Crew start(Simulation sim, RunSettings settings, Journal journal) {
      for (int id : sim.atomIds()) {
        sim.setController(
            id,
            (body, cycle) -> {
              body.command(
                  Atom.target(Leg.PX), LegAngles.swing(0.4 * Math.sin(cycle * 0.3), -Math.PI / 2));
              if (cycle == at) {
                interruption.request();
              }
            });
      }
      return new Crew() {};
    }
  }

  private static Map<String, String> files(Path dir) throws IOException {
    Map<String, String> files = new java.util.TreeMap<>();
    try (Stream<Path> all = Files.list(dir)) {
      for (Path file : all.toList()) {
        files.put(
            file.getFileName().toString(),
            java.util.HexFormat.of()
                .formatHex(
                    java.security.MessageDigest.getInstance("SHA-256")
                        .digest(Files.readAllBytes(file))));
      }
    } catch (java.security.NoSuchAlgorithmException e) {
      throw new AssertionError(e);
    }
    return files;
  }

  @Test
  void aRunThatFailsAtItsStartLeavesThePreviousRunsFilesAsTheyWere() throws IOException {
    run(cycles(5), false, new AtomicLong());
    Files.writeString(dir.resolve("notes.txt"), "mine\n");
    Map<String, String> before = files(dir);
    assertThat(before).containsKeys(SimRun.TRACE, Outputs.TRAJECTORY, "notes.txt");

    assertThatThrownBy(
            () ->
                SimRun.run(
                    new FailingAtStart(),
                    cycles(5),
                    new PrintStream(OutputStream.nullOutputStream()),
                    false,
                    () -> 0))
        .isInstanceOf(IllegalStateException.class)
        .hasMessage("could not reach the broker");

    assertThat(files(dir)).isEqualTo(before);
  }

  @Test
  void aFirstRunThatFailsAtItsStartLeavesNoDirectory() {
    Path out = dir.resolve("runs/scripted");
    RunSettings settings = cycles(5).withOut(out);

    assertThatThrownBy(
            () ->
                SimRun.run(
                    new FailingAtStart(),
                    settings,
                    new PrintStream(OutputStream.nullOutputStream()),
                    false,
                    () -> 0))
        .isInstanceOf(IllegalStateException.class);

    assertThat(out).doesNotExist();
  }

  @Test
  void aCompletedRunReplacesThePreviousRunsFilesAndLeavesOthers() throws IOException {
    run(cycles(5), false, new AtomicLong());
    Files.writeString(dir.resolve("notes.txt"), "mine\n");

    run(cycles(9), false, new AtomicLong());

    assertThat(Files.readAllLines(dir.resolve(SimRun.TRACE))).hasSize(1 + 9);
    assertThat(dir.resolve("notes.txt")).hasContent("mine");
    try (Stream<Path> all = Files.list(dir)) {
      assertThat(all.map(p -> p.getFileName().toString())).noneMatch(n -> n.startsWith("."));
    }
  }

  @Test
  void anInterruptedRunKeepsItsTraceMarkedIncompleteAndItsPicturesAndSaysSo() throws IOException {
    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    try (Interruption interruption = Interruption.manual();
        PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8)) {
      SimExample example = new InterruptedAt(interruption, 7);
      assertThatThrownBy(() -> SimRun.run(example, cycles(20), out, false, () -> 0, interruption))
          .isInstanceOf(RunInterrupted.class);

      List<String> trace = Files.readAllLines(dir.resolve(SimRun.TRACE), StandardCharsets.UTF_8);
      // the header, cycles 0 to 7 (the one it was in when asked), and the mark
      assertThat(trace).hasSize(1 + 8 + 1);
      assertThat(trace.get(8)).startsWith("{\"type\":\"cycle\",\"cycle\":7,");
      assertThat(trace.get(9))
          .isEqualTo("{\"type\":\"incomplete\",\"cycles\":8,\"of\":20,\"reason\":\"interrupted\"}");
      for (String png : List.of(Outputs.TRAJECTORY, Outputs.ENERGY, Outputs.START, Outputs.END)) {
        assertThat(dir.resolve(png)).isNotEmptyFile();
      }
      assertThat(bytes.toString(StandardCharsets.UTF_8))
          .contains(
              "armgals scripted: interrupted after 8 of 20 cycles (0.08 s simulated); the trace up"
                  + " to there (marked incomplete) and the pictures are in "
                  + dir);

      String text = Files.readString(dir.resolve(SimRun.TRACE), StandardCharsets.UTF_8);
      Replay.Verdict verdict = Replay.replay(example, Replay.Header.parse(trace.get(0)), text);
      assertThat(verdict)
          .isInstanceOfSatisfying(
              Replay.ReproducedUpTo.class,
              v -> {
                assertThat(v.cycles()).isEqualTo(8);
                assertThat(v.of()).isEqualTo(20);
                assertThat(v.why()).isEqualTo("the run was interrupted");
              });
      assertThat(verdict.line())
          .startsWith(
              "reproduced exactly up to where the trace stops (the run was interrupted): 8 of 20"
                  + " cycles, trace sha-256 ");
    }
  }

  @Test
  void aRunInterruptedBeforeItsFirstCycleKeepsItsHeaderMarkedIncompleteAndNoPictures()
      throws IOException {
    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    try (Interruption interruption = Interruption.manual();
        PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8)) {
      interruption.request();
      assertThatThrownBy(() -> SimRun.run(example, cycles(20), out, false, () -> 0, interruption))
          .isInstanceOf(RunInterrupted.class);
    }

    List<String> trace = Files.readAllLines(dir.resolve(SimRun.TRACE), StandardCharsets.UTF_8);
    assertThat(trace).hasSize(2);
    assertThat(trace.get(1)).contains("\"cycles\":0,\"of\":20");
    assertThat(dir.resolve(Outputs.TRAJECTORY)).doesNotExist();
    assertThat(bytes.toString(StandardCharsets.UTF_8))
        .contains("interrupted after 0 of 20 cycles (0.00 s simulated); the trace up to there")
        .contains("(marked incomplete) is in " + dir);
    assertThat(
            Replay.replay(
                    example,
                    Replay.Header.parse(trace.get(0)),
                    Files.readString(dir.resolve(SimRun.TRACE), StandardCharsets.UTF_8))
                .line())
        .startsWith(
            "reproduced exactly up to where the trace stops (the run was interrupted): 0 of");
  }

  @Test
  void aTraceCutInTheMiddleOfALineReplaysUpToItsLastWholeLine() throws IOException {
    run(cycles(12), false, new AtomicLong());
    String text = Files.readString(dir.resolve(SimRun.TRACE), StandardCharsets.UTF_8);
    String cut = text.substring(0, text.length() - 40);
    Replay.Header header = Replay.Header.parse(text.lines().findFirst().orElseThrow());

    Replay.Verdict verdict = Replay.replay(example, header, cut);

    assertThat(verdict.line())
        .startsWith(
            "reproduced exactly up to where the trace stops (it stops in the middle of a line: its"
                + " run was killed): 11 of 12 cycles");
    String changed = cut.replaceFirst("\"energy\":[0-9.]+", "\"energy\":1");
    assertThat(Replay.replay(example, header, changed)).isInstanceOf(Replay.Differs.class);
  }

  @Test
  void aRunOfTheLongestDurationCountsItsCyclesWithoutOverflow() {
    Duration longest = Duration.ofSeconds(Long.MAX_VALUE / 1_000_000_000L);

    assertThat(SimRun.cycles(example, settings(OptionalLong.empty(), Optional.of(longest))))
        .isEqualTo(Math.ceilDiv(longest.toNanos(), PERIOD.toNanos()))
        .isGreaterThan(1);
  }
}

package org.armgals.examples.robots;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.StringWriter;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.NavigableMap;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import org.armgals.examples.cli.Armgals;
import org.armgals.examples.cli.Catalog;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.Journal;
import org.armgals.examples.sim.Reflection;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.sim.Vec3;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The {@code distributed} robot: a chain of two atoms whose robots run in two JVMs started by the
 * crew, through an embedded broker on 127.0.0.1, in lock step with the world; its meta level, in
 * the world's JVM, reflects on them across JVMs.
 */
class DistributedTest {
  /** A battery that falls under half in 0.55 to 0.75 s of the crawl. */
  private static final double SMALL_BATTERY = 1;

  private static final long PERIOD_NANOS = 10_000_000;

  @Test
  void theMetaLevelInTheWorldsJvmLowersEachStrokeFromTheCycleAfterItsThresholdInEveryRun(
      @TempDir Path dir) throws Exception {
    Distributed example = new Distributed(SMALL_BATTERY);
    RunSettings settings = settings(dir, 2);

    Run first = run(example, settings, 100, dir.resolve("first"));
    Run second = run(example, settings, 100, dir.resolve("second"));

    long self = ProcessHandle.current().pid();
    assertThat(first.joined).extracting(DistributedWire.Joined::atom).containsExactly(1, 2);
    assertThat(first.joined)
        .extracting(DistributedWire.Joined::pid)
        .doesNotContain(self)
        .doesNotHaveDuplicates()
        .containsExactlyElementsOf(first.children.stream().map(ProcessHandle::pid).toList());
    assertThat(first.children).noneMatch(ProcessHandle::isAlive);
    assertThat(first.taken).containsExactly("crawler-a1", "crawler-a2");
    for (int atom : new int[] {1, 2}) {
      DistributedMeta.Decision d = first.decisions.get(atom);
      assertThat(d).as("the meta's request to atom %d", atom).isNotNull();
      assertThat(d.fraction()).isLessThan(0.5);
      assertThat(d.fromNanos()).isEqualTo(d.thresholdNanos() + PERIOD_NANOS);
      assertThat(first.applied.get(atom)).as("atom %d acknowledged it applied", atom).isTrue();
      NavigableMap<Long, Double> strokes = first.strokes.get(atom);
      // What the world received: the full stroke up to the time the request names, the gentler one
      // from its readings on, whenever the atom's island applied the request.
      assertThat(strokes.headMap(d.fromNanos(), false).values())
          .isNotEmpty()
          .allSatisfy(s -> assertThat(s).isCloseTo(DistributedGait.SWING, within(1e-9)));
      assertThat(strokes.tailMap(d.fromNanos(), true).values())
          .hasSizeGreaterThan(10)
          .allSatisfy(s -> assertThat(s).isCloseTo(DistributedMeta.GENTLE_SWING, within(1e-9)));
      assertThat(first.trace)
          .contains(
              "adaptation: stroke 0.45 → 0.25 rad from "
                  + String.format(java.util.Locale.ROOT, "%.2f s", d.fromNanos() / 1e9));
      // The loop's record: the request from the meta's side (the world's JVM), decided on the
      // threshold's cycle, and applied on the robot's side, as the atom's JVM recorded it, in that
      // cycle still (the world waited for the acknowledgement before the next readings).
      long cycle = d.thresholdNanos() / PERIOD_NANOS;
      String robot = DistributedCrawler.robotName(atom);
      assertThat(first.loop)
          .contains(
              String.format(
                  "{\"cycle\":%d,\"meta\":\"%s\",\"event\":\"requested\",\"robot\":\"%s\","
                      + "\"version\":%d,",
                  cycle, DistributedMeta.NAME, robot, d.version()))
          .contains(
              String.format(
                  "{\"cycle\":%d,\"event\":\"applied\",\"robot\":\"%s\",\"version\":%d,",
                  cycle, robot, d.version()));
    }
    assertThat(first.loopFigures)
        .contains(
            new Summary.Entry(
                "meta level",
                "in the world's JVM, apart from every atom's, over the broker; in lock step, one"
                    + " cycle behind"),
            new Summary.Entry("requests", "2 (2 applied, 0 refused, 0 held back by its damping)"),
            new Summary.Entry("notified to applied", "0 cycles (median), 0 at most (p99 0)"));
    // Every notification the robots sent (each JVM counts its own) reached the meta; its filter
    // let through the two threshold meta-events only.
    assertThat(first.loopFigures)
        .filteredOn(e -> e.name().equals("notifications"))
        .singleElement()
        .satisfies(
            e -> assertThat(e.value()).matches("(\\d+) sent, \\1 received, 2 through its filter"));
    // Seen: about 4 cm towards -x in 1 s, the last third of it with the gentler stroke.
    assertThat(first.start.x() - first.end.x()).isGreaterThan(0.02);
    // The world's lock step holds the meta too: the same trace, journal included, twice.
    assertThat(second.trace)
        .as("missed cycles: %d, then %d", first.missed, second.missed)
        .isEqualTo(first.trace);
    assertThat(second.decisions).isEqualTo(first.decisions);
    assertThat(second.loop).isEqualTo(first.loop);
  }

  @Test
  void killingAnAtomsJvmLeavesTheWorldTheMetaAndTheOtherAtomRunning(@TempDir Path dir)
      throws Exception {
    Distributed example = new Distributed();
    RunSettings settings = settings(dir, 2);
    List<String> notes = new ArrayList<>();
    try (Simulation sim =
        Simulation.builder(example.scene(settings)).controlPeriod(settings.period()).build()) {
      DistributedCrew crew = (DistributedCrew) example.start(sim, settings, journal(sim, notes));
      ProcessHandle second;
      try {
        sim.runCycles(30);
        second = crew.processes().get(1);
        second.destroyForcibly();
        assertThat(second.onExit().get(30, TimeUnit.SECONDS).isAlive()).isFalse();
        sim.runCycles(30);

        assertThat(crew.missedCycles(2)).isGreaterThanOrEqualTo(30);
        // Atom 1 answered the readings of the last cycle: the world did not wait for atom 2.
        assertThat(crew.strokes(1).lastKey()).isEqualTo(59 * PERIOD_NANOS);
        assertThat(crew.metaLevel().model(1).lastSeq()).isPositive();
        assertThat(notes).contains("2: its JVM ended: the world goes on without its robot");
      } finally {
        crew.close();
      }
      assertThat(crew.processes()).noneMatch(ProcessHandle::isAlive);
    }
    // Unfinished, the run leaves the atoms' logs only: no side of the loop's record.
    try (var files = java.nio.file.Files.list(dir)) {
      assertThat(files.map(f -> f.getFileName().toString()))
          .containsExactlyInAnyOrder("atom-1.log", "atom-2.log");
    }
  }

  @Test
  void metaRemoteIsAUsageErrorSayingTheMetaIsApartAlready(@TempDir Path dir) {
    RunSettings settings = settings(dir, 2).withMeta(RunSettings.MetaPlace.REMOTE);
    assertThatThrownBy(() -> new Distributed().scene(settings))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageStartingWith("--meta remote: ");
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    ByteArrayOutputStream err = new ByteArrayOutputStream();

    int status =
        Armgals.execute(
            Catalog.of(List.of(new Distributed())),
            new PrintStream(out, true, StandardCharsets.UTF_8),
            new PrintStream(err, true, StandardCharsets.UTF_8),
            "run",
            "distributed",
            "--meta",
            "remote",
            "--out",
            dir.resolve("run").toString());

    assertThat(status).isEqualTo(Armgals.USAGE);
    assertThat(err.toString(StandardCharsets.UTF_8).strip())
        .isEqualTo(
            "armgals: --meta remote: 'distributed' runs its meta level in the world's JVM, apart"
                + " from every atom's JVM already; leave --meta out");
    assertThat(dir.resolve("run")).doesNotExist(); // refused before anything started
  }

  @Test
  void aGaitSwingsTheNewAmplitudeOnlyForReadingsFromTheTimeItNames() {
    DistributedCrawler.Gait gait = new DistributedCrawler.Gait("gait", 0.45).from(1_000, 0.25);

    assertThat(gait.swingAt(999)).isEqualTo(0.45);
    assertThat(gait.swingAt(1_000)).isEqualTo(0.25);
    assertThat(gait.swingAt(5_000)).isEqualTo(0.25);
    assertThatThrownBy(() -> gait.from(2_000, 0.6))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("swing 0.6 rad");
    assertThatThrownBy(() -> gait.from(-1, 0.2))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("fromNanos -1");
  }

  @Test
  void anUnreachableBrokerIsAUsageErrorThatSaysWhatToDo(@TempDir Path dir) throws IOException {
    int closedPort;
    try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      closedPort = socket.getLocalPort();
    }
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    ByteArrayOutputStream err = new ByteArrayOutputStream();

    int status =
        Armgals.execute(
            Catalog.of(List.of(new Distributed())),
            new PrintStream(out, true, StandardCharsets.UTF_8),
            new PrintStream(err, true, StandardCharsets.UTF_8),
            "run",
            "distributed",
            "--broker",
            "tcp://127.0.0.1:" + closedPort,
            "--out",
            dir.toString());

    String message = err.toString(StandardCharsets.UTF_8);
    assertThat(status).isEqualTo(Armgals.USAGE);
    assertThat(message.strip())
        .startsWith("armgals: could not reach the broker at tcp://127.0.0.1:" + closedPort)
        .contains("leave --broker out")
        .doesNotContain("\n");
  }

  @Test
  void atomsOutsideTwoToSixAreRefusedNamingTheValueAndTheRange(@TempDir Path dir) {
    Distributed example = new Distributed();
    for (int atoms : new int[] {1, 7}) {
      RunSettings settings = settings(dir, atoms);
      assertThatThrownBy(() -> example.scene(settings))
          .isInstanceOf(IllegalArgumentException.class)
          .hasMessageContaining("--atoms " + atoms)
          .hasMessageContaining("2 to 6");
    }
  }

  /** What a test looks at of one run. */
  private record Run(
      String trace,
      String loop,
      List<Summary.Entry> loopFigures,
      List<ProcessHandle> children,
      List<DistributedWire.Joined> joined,
      List<String> taken,
      Map<Integer, DistributedMeta.Decision> decisions,
      Map<Integer, Boolean> applied,
      Map<Integer, NavigableMap<Long, Double>> strokes,
      long missed,
      Vec3 start,
      Vec3 end) {}

  /** A run of {@code cycles} cycles, its trace kept with the notes of its journal. */
  private static Run run(Distributed example, RunSettings settings, int cycles, Path loopDir)
      throws IOException {
    java.nio.file.Files.createDirectories(loopDir);
    List<Summary.Entry> loopFigures;
    StringWriter trace = new StringWriter();
    Map<Integer, DistributedMeta.Decision> decisions = new TreeMap<>();
    Map<Integer, Boolean> applied = new TreeMap<>();
    Map<Integer, NavigableMap<Long, Double>> strokes = new TreeMap<>();
    DistributedCrew crew;
    Vec3 start;
    Vec3 end;
    long missed;
    List<String> taken;
    try (Simulation sim =
        Simulation.builder(example.scene(settings))
            .seed(settings.seed())
            .controlPeriod(settings.period())
            .trace(trace)
            .build()) {
      start = centre(sim);
      crew = (DistributedCrew) example.start(sim, settings, journal(sim, new ArrayList<>()));
      try {
        sim.runCycles(cycles);
        loopFigures = crew.finish(loopDir);
        missed = crew.missedCycles();
        end = centre(sim);
        taken = crew.metaLevel().baseLevelEntities();
        for (DistributedWire.Joined j : crew.joined()) {
          crew.metaLevel().decision(j.atom()).ifPresent(d -> decisions.put(j.atom(), d));
          applied.put(j.atom(), crew.metaLevel().applied(j.atom()));
          strokes.put(j.atom(), new TreeMap<>(crew.strokes(j.atom())));
        }
      } finally {
        crew.close();
      }
    }
    return new Run(
        trace.toString(),
        java.nio.file.Files.readString(loopDir.resolve(Reflection.LOOP)),
        loopFigures,
        crew.processes(),
        crew.joined(),
        taken,
        decisions,
        applied,
        strokes,
        missed,
        start,
        end);
  }

  /** A journal that writes into the trace, as a run's does, and keeps the notes. */
  private static Journal journal(Simulation sim, List<String> notes) {
    return new Journal() {
      @Override
      public void adaptation(int atom, String what, String why) {
        sim.note(atom, "adaptation: " + what + ", because " + why);
      }

      @Override
      public void note(int atom, String text) {
        notes.add(atom + ": " + text);
        sim.note(atom, text);
      }
    };
  }

  private static RunSettings settings(Path dir, int atoms) {
    return new RunSettings(
        OptionalLong.empty(),
        Optional.empty(),
        Duration.ofNanos(PERIOD_NANOS),
        1,
        Optional.of(atoms),
        false,
        Optional.empty(),
        dir);
  }

  private static Vec3 centre(Simulation sim) {
    double x = 0;
    double y = 0;
    double z = 0;
    for (int id : sim.atomIds()) {
      Vec3 p = sim.sensors(id).position();
      x += p.x();
      y += p.y();
      z += p.z();
    }
    int n = sim.atomIds().size();
    return new Vec3(x / n, y / n, z / n);
  }
}

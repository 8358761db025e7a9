package org.armgals.examples.robots;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import org.armgals.examples.cli.RunSettings;
import org.armgals.examples.cli.Summary;
import org.armgals.examples.robots.CaterpillarModules.Pacemaker;
import org.armgals.examples.robots.CaterpillarSignals.Beat;
import org.armgals.examples.robots.CaterpillarSignals.Travel;
import org.armgals.examples.robots.GaitsTestSupport.TestJournal;
import org.armgals.examples.sim.Crew;
import org.armgals.maam.Adaptation;
import org.armgals.maam.CycleReport;
import org.armgals.maam.PortRef;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.LegBinding;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CaterpillarTest {

  private final Caterpillar caterpillar = new Caterpillar();

  @Test
  void chainCrawlsForwardStaysBoundAndItsMetaLevelLengthensTheStride() {
    RunSettings settings = GaitsTestSupport.settings(Optional.empty());
    try (Simulation sim = Simulation.builder(caterpillar.scene(settings)).build()) {
      TestJournal journal = new TestJournal(sim::timeNanos);
      List<Integer> ids = sim.atomIds();
      assertThat(ids).hasSize(Caterpillar.DEFAULT_ATOMS);
      double startX = centreX(sim);
      try (Crew crew = caterpillar.start(sim, settings, journal)) {
        sim.runCycles(320); // 3.2 s: four steps
        assertThat(figure(crew.figures(), "module errors")).isEqualTo("0");
      }
      // Forward (towards the head, +x) by centimetres: about 6 cm with the atom of today.
      assertThat(centreX(sim) - startX).isGreaterThan(0.03);
      for (int i = 0; i + 1 < ids.size(); i++) {
        assertThat(sim.body(ids.get(i)).read(Atom.binding(CaterpillarModules.FRONT)))
            .as("atom %d's front leg", ids.get(i))
            .isInstanceOf(LegBinding.Bound.class);
      }
      for (int id : ids) {
        assertThat(sim.atom(id).sensors().tilt()).as("atom %d's tilt", id).isLessThan(0.5);
      }
      // The short first stride makes too little progress: the meta level lengthened it.
      assertThat(journal.adaptations).isNotEmpty();
      assertThat(journal.adaptations.get(0)).contains("stride 0.20 -> 0.30");
    }
  }

  @Test
  void metaLevelLengthensTheStrideOnlyWhileStepsAreShort() {
    Pacemaker pacemaker = new Pacemaker(CaterpillarSegment.PACEMAKER, 0.8, 0.2, 0.25, 0.01, 0);
    TestJournal journal = new TestJournal(() -> 0);
    CaterpillarMeta meta = new CaterpillarMeta(pacemaker, journal, 1);
    List<Adaptation> requests = new ArrayList<>();
    // Six steps of 5 cm: fast enough, nothing to do.
    feedSteps(meta, requests, 0, 6, 0.05);
    assertThat(requests).isEmpty();
    // Then steps of 1 cm: a longer stride after the dwell, and again, up to the cone's limit.
    feedSteps(meta, requests, 0.30, 12, 0.01);
    assertThat(requests).hasSize(3).allMatch(a -> a instanceof Adaptation.ChangeModule);
    assertThat(meta.stride()).isEqualTo(CaterpillarTuning.MAX_STRIDE);
    assertThat(journal.adaptations).hasSize(3);
    assertThat(journal.adaptations.get(0)).contains("stride 0.20 -> 0.30", "advanced 1.0 cm");
  }

  @Test
  void chainLengthOutsideTwoToEightIsRefusedNamingIt() {
    assertThatThrownBy(() -> caterpillar.scene(GaitsTestSupport.settings(Optional.of(9))))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("--atoms 9")
        .hasMessageContaining("between 2 and 8");
    assertThatThrownBy(() -> caterpillar.scene(GaitsTestSupport.settings(Optional.of(1))))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("--atoms 1");
    assertThat(caterpillar.scene(GaitsTestSupport.settings(Optional.of(8))).atoms()).hasSize(8);
  }

  @Test
  void runLeavesTraceAndPicturesAndTellsTheAdaptation(@TempDir Path out) {
    RunSettings settings = GaitsTestSupport.settings(Optional.of(3), OptionalLong.of(260), out);
    Summary summary =
        caterpillar.run(settings, new java.io.PrintStream(java.io.OutputStream.nullOutputStream()));
    assertThat(figure(summary.entries(), "adaptations")).isNotEqualTo("0");
    assertThat(summary.entries()).anyMatch(e -> e.value().contains("stride 0.20 -> 0.30"));
    assertThat(figure(summary.entries(), "bonds held")).isEqualTo("2 of 2");
    for (String file :
        List.of(
            "trace.jsonl",
            "trajectory.png",
            "energy.png",
            "adaptations.png",
            "molecule-start.png",
            "molecule-end.png")) {
      assertThat(out.resolve(file)).as(file).exists();
    }
  }

  private static void feedSteps(
      CaterpillarMeta meta, List<Adaptation> requests, double x0, int steps, double perStep) {
    int perStepCycles = 80;
    for (int i = 0; i <= steps * perStepCycles; i++) {
      double phase = (i % perStepCycles) / (double) perStepCycles;
      double x = x0 + perStep * i / perStepCycles;
      CycleReport report =
          new CycleReport(
              "segment1",
              i,
              i * 10_000_000L,
              List.of(
                  new CycleReport.Emission(
                      new PortRef(CaterpillarSegment.PACEMAKER, CaterpillarSignals.BEAT),
                      new Beat(phase, 0.8, meta.stride())),
                  new CycleReport.Emission(
                      new PortRef("odometer", CaterpillarSignals.TRAVEL), new Travel(x, 0))),
              List.of(),
              List.of(),
              List.of());
      meta.onCycle(report, requests::add);
    }
  }

  private static double centreX(Simulation sim) {
    return sim.atomIds().stream()
        .mapToDouble(id -> sim.atom(id).sensors().position().x())
        .average()
        .orElseThrow();
  }

  private static String figure(List<Summary.Entry> entries, String name) {
    return entries.stream()
        .filter(e -> e.name().equals(name))
        .map(Summary.Entry::value)
        .findFirst()
        .orElseThrow(() -> new AssertionError("no figure '" + name + "' in " + entries));
  }
}

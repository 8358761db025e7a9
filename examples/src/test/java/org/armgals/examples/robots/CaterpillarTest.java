package org.armgals.examples.robots;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalLong;
import org.armgals.active.Address;
import org.armgals.examples.robots.GaitsTestSupport.TestJournal;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.Crew;
import org.armgals.kernel.BehavioralMeta;
import org.armgals.kernel.Entity;
import org.armgals.kernel.ModelView;
import org.armgals.kernel.StateEvent;
import org.armgals.kernel.spi.MetaContext;
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
        assertThat(sim.sensors(id).tilt()).as("atom %d's tilt", id).isLessThan(0.5);
      }
      // The short first stride makes too little progress: the meta level lengthened it.
      assertThat(journal.adaptations).isNotEmpty();
      assertThat(journal.adaptations.get(0)).contains("stride 0.20 -> 0.30");
    }
  }

  @Test
  void metaLevelLengthensTheStrideOnlyWhileStepsAreShort() {
    CaterpillarMeta meta = new CaterpillarMeta("bmrobot");
    RecordingContext context = new RecordingContext();
    // Six steps of 6 cm: fast enough, nothing to do.
    feedSteps(meta, context, 0, 6, 0.06);
    assertThat(context.requests).isEmpty();
    // Then steps of 1 cm: a longer stride after the dwell, and again, up to the cone's limit.
    feedSteps(meta, context, 0.36, 12, 0.01);
    assertThat(context.requests)
        .hasSize(3)
        .allMatch(
            a ->
                a instanceof org.armgals.kernel.Adaptation.ApplyBehavior b
                    && b.behavior().equals("changeModule")
                    && b.input() instanceof Map<?, ?> m
                    && CaterpillarSegment.PACEMAKER.equals(m.get("name")));
    assertThat(meta.stride()).isEqualTo(CaterpillarTuning.MAX_STRIDE);
    assertThat(org.armgals.maam.RobotKind.reason(context.requests.get(0)))
        .hasValueSatisfying(
            why -> assertThat(why).contains("stride 0.20 -> 0.30").contains("advanced 1.0 cm"));
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
      CaterpillarMeta meta, RecordingContext context, double x0, int steps, double perStep) {
    int perStepCycles = 80;
    for (int i = 0; i <= steps * perStepCycles; i++) {
      double phase = (i % perStepCycles) / (double) perStepCycles;
      double x = x0 + perStep * i / perStepCycles;
      Map<String, Object> seen = new LinkedHashMap<>();
      seen.put("cycle", (long) i);
      seen.put("program", 1L);
      seen.put("errors", 0L);
      seen.put(CaterpillarSegment.PHASE, phase);
      seen.put(CaterpillarSegment.X, x);
      meta.onNotification(
          context, new StateEvent(HEAD, META, context.seq++, i * 10_000_000L, "cycle", seen, true));
    }
  }

  private static final Address HEAD = new Address("test", 1);
  private static final Address META = new Address("test", 2);

  /** What the policy asked of its meta-entity: a stand-in for the kernel's, recording requests. */
  private static final class RecordingContext implements MetaContext {
    final List<org.armgals.kernel.Adaptation> requests = new ArrayList<>();
    long seq = 1;

    @Override
    public BehavioralMeta self() {
      throw new UnsupportedOperationException("not used by the policy");
    }

    @Override
    public Entity entity(Address entity) {
      throw new UnsupportedOperationException("not used by the policy");
    }

    @Override
    public ModelView model(Address entity) {
      throw new UnsupportedOperationException("not used by the policy");
    }

    @Override
    public OptionalLong adapt(Address entity, org.armgals.kernel.Adaptation adaptation) {
      requests.add(adaptation);
      return OptionalLong.of(requests.size());
    }

    @Override
    public void setFilter(Address entity, String selector) {
      throw new UnsupportedOperationException("not used by the policy");
    }

    @Override
    public long nanoTime() {
      return 0;
    }
  }

  private static double centreX(Simulation sim) {
    return sim.atomIds().stream()
        .mapToDouble(id -> sim.sensors(id).position().x())
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

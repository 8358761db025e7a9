package org.armgals.examples.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import org.armgals.examples.robots.Caterpillar;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.maam.sim.Simulation;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The reflective side of a run: a lock-step run is the same whatever the number of threads, and the
 * reactive level is autonomous (paper §5.1): a meta level whose JVM is killed leaves the robots
 * running their last program, and the loss is reported.
 */
class ReflectionTest {
  private static final Caterpillar CATERPILLAR = new Caterpillar();

  private static RunSettings settings(Path out, long cycles) {
    return new RunSettings(
        OptionalLong.of(cycles),
        Optional.empty(),
        Duration.ofMillis(10),
        1,
        Optional.of(3),
        false,
        Optional.empty(),
        out);
  }

  @Test
  void aLockStepRunIsTheSameWhateverTheNumberOfWorkers(@TempDir Path dir) throws Exception {
    int before = Reflection.WORKERS.get();
    try {
      for (int workers : new int[] {1, 4}) {
        Reflection.WORKERS.set(workers);
        CATERPILLAR.run(
            settings(dir.resolve("w" + workers), 200),
            new java.io.PrintStream(java.io.OutputStream.nullOutputStream()));
      }
    } finally {
      Reflection.WORKERS.set(before);
    }
    for (String file : List.of("trace.jsonl", Reflection.LOOP)) {
      assertThat(Files.readString(dir.resolve("w4").resolve(file)))
          .as(file)
          .isEqualTo(Files.readString(dir.resolve("w1").resolve(file)));
    }
  }

  @Test
  void robotsWhoseMetaJvmIsKilledRunOnAndTheLossIsReported(@TempDir Path out) throws Exception {
    RunSettings settings = settings(out, 300).withMeta(RunSettings.MetaPlace.REMOTE);
    List<String> adaptations = new java.util.ArrayList<>();
    Journal journal =
        new Journal() {
          @Override
          public void adaptation(int atom, String what, String why) {
            adaptations.add(what);
          }

          @Override
          public void note(int atom, String text) {}
        };
    try (Simulation sim = Simulation.builder(CATERPILLAR.scene(settings)).build();
        Crew crew = CATERPILLAR.start(sim, settings, journal)) {
      Reflection reflection = crew.reflection().orElseThrow();
      sim.runCycles(210); // the meta lengthened the stride once, at 2.0 s
      assertThat(adaptations).hasSize(1);
      reflection.killMeta();
      sim.runCycles(90); // in lock step, the robots wait for the meta until presence says lost
      List<Summary.Entry> figures = reflection.finish(out);

      assertThat(sim.cycle()).isEqualTo(300);
      assertThat(figures)
          .anySatisfy(
              e -> {
                assertThat(e.name()).isEqualTo("meta level lost");
                assertThat(e.value()).contains("lost").contains("ran on");
              });
      assertThat(Files.readString(out.resolve(Reflection.LOOP)))
          .contains("\"event\":\"meta-lost\"")
          .contains("\"event\":\"free\"");
    }
  }

  @Test
  void everyExampleWithAMetaLevelIsFoundByTheMetaLevelsJvm() {
    RunSettings settings = settings(java.nio.file.Path.of("unused"), 1);
    for (org.armgals.examples.run.Example e : org.armgals.examples.cli.Catalog.standard().all()) {
      if (e instanceof SimExample sim && sim.metaLevel(settings).isPresent()) {
        assertThat(MetaMain.find(e.name())).as(e.name()).isPresent();
      }
    }
  }
}

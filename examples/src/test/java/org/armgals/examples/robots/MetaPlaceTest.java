package org.armgals.examples.robots;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import java.util.OptionalLong;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.Reflection;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The same meta code in the robots' JVM or in a JVM of its own (paper §2.3: the meta level may live
 * elsewhere): in lock step on virtual time the run is the same, bit for bit, its trace and its
 * reflective loop's record, whatever the place of the meta.
 */
class MetaPlaceTest {
  private static final PrintStream QUIET = new PrintStream(OutputStream.nullOutputStream());

  /** 260 cycles of a 3-atom caterpillar: its meta level lengthens the stride once by then. */
  private static Summary run(Path out, RunSettings.MetaPlace place) {
    RunSettings settings =
        GaitsTestSupport.settings(Optional.of(3), OptionalLong.of(260), out).withMeta(place);
    return new Caterpillar().run(settings, QUIET);
  }

  @Test
  void aLockStepRunIsTheSameWithTheMetaInItsOwnJvm(@TempDir Path dir) throws Exception {
    Path local = dir.resolve("local");
    Path remote = dir.resolve("remote");
    Summary here = run(local, RunSettings.MetaPlace.LOCAL);
    Summary there = run(remote, RunSettings.MetaPlace.REMOTE);

    assertThat(Files.readString(remote.resolve("trace.jsonl")))
        .isEqualTo(Files.readString(local.resolve("trace.jsonl")));
    String loop = Files.readString(local.resolve(Reflection.LOOP));
    assertThat(loop).contains("\"event\":\"received\"").contains("\"event\":\"applied\"");
    assertThat(Files.readString(remote.resolve(Reflection.LOOP))).isEqualTo(loop);
    assertThat(figure(there, "adaptations"))
        .isEqualTo(figure(here, "adaptations"))
        .isNotEqualTo("0");
    assertThat(figure(there, "meta level")).startsWith("remote");
    assertThat(figure(there, "stride")).isEqualTo(figure(here, "stride"));
  }

  private static String figure(Summary summary, String name) {
    return summary.entries().stream()
        .filter(e -> e.name().equals(name))
        .map(Summary.Entry::value)
        .findFirst()
        .orElseThrow(() -> new AssertionError("no figure '" + name + "' in " + summary.entries()));
  }
}

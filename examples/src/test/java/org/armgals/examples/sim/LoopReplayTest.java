package org.armgals.examples.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Optional;
import java.util.OptionalLong;
import org.armgals.examples.robots.Caterpillar;
import org.armgals.examples.run.RunSettings;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A run's reflective loop replayed: a run in lock step leaves the same trace and the same loop's
 * record again; a free run (paced to real time, its robots never waiting for their meta level) is
 * reproduced by applying the meta level's requests where its record says they were applied.
 */
class LoopReplayTest {
  private static final Caterpillar CATERPILLAR = new Caterpillar();

  private static RunSettings settings(Path out, long cycles, boolean realTime) {
    return new RunSettings(
        OptionalLong.of(cycles),
        Optional.empty(),
        Duration.ofMillis(10),
        1,
        Optional.of(3),
        realTime,
        Optional.empty(),
        out);
  }

  private static Replay.Verdict replay(Path out) throws Exception {
    String trace = Files.readString(out.resolve("trace.jsonl"));
    Replay.Header header = Replay.Header.parse(trace.lines().findFirst().orElseThrow());
    return Replay.replay(CATERPILLAR, header, trace, out);
  }

  @Test
  void aLockStepRunReplaysItsTraceAndItsLoopsRecord(@TempDir Path out) throws Exception {
    CATERPILLAR.run(settings(out, 200, false), new PrintStream(OutputStream.nullOutputStream()));

    assertThat(replay(out)).isInstanceOf(Replay.Reproduced.class);

    // A loop's record changed by hand is caught, at its cycle.
    Path loop = out.resolve(Reflection.LOOP);
    Files.writeString(
        loop, Files.readString(loop).replaceFirst("\"passed\":true", "\"passed\":false"));
    assertThat(replay(out))
        .isInstanceOfSatisfying(
            Replay.Differs.class,
            d -> assertThat(d.detail()).contains("reflective loop's record").contains("passed"));
  }

  @Test
  void aFreeRunReplaysWithItsMetaLevelsRequestsWhereTheyWereApplied(@TempDir Path out)
      throws Exception {
    CATERPILLAR.run(settings(out, 300, true), new PrintStream(OutputStream.nullOutputStream()));
    String trace = Files.readString(out.resolve("trace.jsonl"));
    assertThat(trace.lines().findFirst().orElseThrow()).contains("\"pacing\":\"free\"");
    assertThat(Files.readString(out.resolve(Reflection.LOOP))).contains("\"event\":\"applied\"");

    assertThat(replay(out)).isInstanceOf(Replay.Reproduced.class);

    // Without the record, a free run cannot be replayed, and says why.
    Files.delete(out.resolve(Reflection.LOOP));
    assertThat(replay(out))
        .isInstanceOfSatisfying(
            Replay.Differs.class, d -> assertThat(d.detail()).contains("loop's record"));
  }
}

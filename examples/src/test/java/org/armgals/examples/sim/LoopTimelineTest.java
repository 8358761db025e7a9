package org.armgals.examples.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import javax.imageio.ImageIO;
import org.armgals.examples.plot.LoopPicture.Kind;
import org.armgals.examples.plot.LoopPicture.Link;
import org.armgals.examples.plot.LoopPicture.Step;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The loop's record read as its picture shows it. */
class LoopTimelineTest {
  private static final Duration PERIOD = Duration.ofMillis(10);

  @TempDir Path dir;

  /** A small loop record, as LoopRecorder writes one: the energy robot's filter change. */
  private static final String RECORD =
      """
      {"cycle":-1,"meta":"bmenergy","event":"filter","robot":"energy","selector":"kind = 'threshold'"}
      {"cycle":0,"event":"notified","robot":"energy","kind":"state"}
      {"cycle":0,"meta":"bmenergy","event":"received","robot":"energy","kind":"state","passed":false}
      {"cycle":1,"event":"notified","robot":"energy","kind":"state"}
      {"cycle":1,"meta":"bmenergy","event":"received","robot":"energy","kind":"state","passed":false}
      {"cycle":2,"event":"notified","robot":"energy","kind":"threshold"}
      {"cycle":2,"meta":"bmenergy","event":"received","robot":"energy","kind":"threshold","passed":true}
      {"cycle":2,"meta":"bmenergy","event":"filter","robot":"energy","selector":""}
      {"cycle":2,"meta":"bmenergy","event":"requested","robot":"energy","version":1,"request":"changeModule stepper {gait=saving}","reason":"battery at 30%","held":true,"cause":"energy#3"}
      {"cycle":2,"meta":"bmenergy","event":"requested","robot":"energy","version":2,"request":"addSchema climb","held":true,"cause":"energy#3"}
      {"cycle":2,"meta":"bmenergy","event":"suppressed","robot":"energy","request":"setScheduling [a, b]"}
      {"cycle":3,"event":"applied","robot":"energy","version":1,"request":"changeModule stepper {gait=saving}","reason":"battery at 30%"}
      {"cycle":3,"event":"notified","robot":"energy","kind":"state"}
      {"cycle":3,"meta":"bmenergy","event":"received","robot":"energy","kind":"state","passed":true}
      {"cycle":4,"event":"refused","robot":"energy","version":2,"request":"addSchema climb","refusal":"no schema 'climb' in the kind"}
      {"cycle":4,"meta":"bmenergy","event":"note","robot":"energy","text":"the saving gait draws 0.45 W"}
      {"cycle":5,"event":"meta-lost","robot":"energy","runtime":"meta-1","reason":"gone"}
      {"cycle":5,"event":"free","robot":"energy","reason":"meta lost"}
      """;

  private Path write(String text) throws IOException {
    Path file = dir.resolve(Reflection.LOOP);
    Files.writeString(file, text, StandardCharsets.UTF_8);
    return file;
  }

  @Test
  void eachRecordIsAStepAtItsCycleAndEachRequestIsLinkedToItsAnswer() throws IOException {
    LoopTimeline timeline = LoopTimeline.read(write(RECORD), PERIOD);

    assertThat(timeline.metaLevel()).isTrue();
    assertThat(timeline.steps())
        .containsExactly(
            new Step(0, "energy", Kind.FILTER, "kind = 'threshold'"),
            new Step(0, "energy", Kind.SENT, ""),
            new Step(0, "energy", Kind.FILTERED_OUT, ""),
            new Step(0.01, "energy", Kind.SENT, ""),
            new Step(0.01, "energy", Kind.FILTERED_OUT, ""),
            new Step(0.02, "energy", Kind.SENT, "threshold"),
            new Step(0.02, "energy", Kind.PASSED, "threshold"),
            new Step(0.02, "energy", Kind.FILTER, "no selector: all pass"),
            new Step(0.02, "energy", Kind.REQUESTED, "changeModule stepper {gait=saving}"),
            new Step(0.02, "energy", Kind.REQUESTED, "addSchema climb"),
            new Step(0.02, "energy", Kind.HELD_BACK, "setScheduling [a, b]"),
            new Step(0.03, "energy", Kind.APPLIED, "+1 cycle (10 ms)"),
            new Step(0.03, "energy", Kind.SENT, ""),
            new Step(0.03, "energy", Kind.PASSED, ""),
            new Step(
                0.04, "energy", Kind.REFUSED, "+2 cycles (20 ms): no schema 'climb' in the kind"),
            new Step(0.04, "energy", Kind.NOTE, "the saving gait draws 0.45 W"),
            new Step(0.05, "energy", Kind.META_LOST, "meta-1: gone"),
            new Step(0.05, "energy", Kind.FREE, "meta lost"));
    assertThat(timeline.links())
        .containsExactly(
            new Link("energy", 0.02, 0.03, true), new Link("energy", 0.02, 0.04, false));
  }

  @Test
  void itIsDrawnOverTheRun() throws IOException {
    Path png = dir.resolve(Outputs.LOOP);
    LoopTimeline.read(write(RECORD), PERIOD).write("energy: the reflective loop", 0.06, png);

    assertThat(ImageIO.read(png.toFile())).isNotNull();
  }

  @Test
  void aRecordWithoutAStepOfAMetaTellsNoMetaLevel() throws IOException {
    assertThat(LoopTimeline.read(write(""), PERIOD).metaLevel()).isFalse();
    assertThat(
            LoopTimeline.read(
                    write(
                        "{\"cycle\":0,\"event\":\"notified\",\"robot\":\"r\",\"kind\":\"state\"}"),
                    PERIOD)
                .metaLevel())
        .isFalse();
  }

  @Test
  void aLineThatIsNotARecordOfTheLoopIsRefusedByNumber() throws IOException {
    Path file = write("{\"cycle\":0,\"event\":\"notified\",\"robot\":\"r\"}\n{\"cycle\":1}\n");

    assertThatThrownBy(() -> LoopTimeline.read(file, PERIOD))
        .isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("line 2");
  }
}

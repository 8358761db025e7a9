package org.armgals.examples.plot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import org.armgals.examples.plot.LoopPicture.Kind;
import org.armgals.examples.plot.LoopPicture.Link;
import org.armgals.examples.plot.LoopPicture.Step;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The picture of a reflective loop: a row per kind of step and robot, thousands of notifications
 * drawn, each request linked to its application; bad input refused by name.
 */
class LoopPictureTest {
  @TempDir Path dir;

  /** A small loop of one robot: 1,500 notifications, a filter change, one request applied. */
  private static List<Step> loop(String robot) {
    List<Step> steps = new ArrayList<>();
    steps.add(new Step(0, robot, Kind.FILTER, "kind = 'threshold'"));
    for (int i = 0; i < 1500; i++) {
      double t = i * 0.01;
      steps.add(new Step(t, robot, Kind.SENT, ""));
      steps.add(new Step(t, robot, i < 900 ? Kind.FILTERED_OUT : Kind.PASSED, ""));
    }
    steps.add(new Step(9, robot, Kind.SENT, "threshold"));
    steps.add(new Step(9, robot, Kind.FILTER, "kind = 'threshold' OR kind = 'state'"));
    steps.add(new Step(9, robot, Kind.REQUESTED, "changeModule stepper {gait=saving}"));
    steps.add(new Step(9.01, robot, Kind.APPLIED, "+1 cycle (10 ms)"));
    steps.add(new Step(9, robot, Kind.NOTE, "low battery"));
    return steps;
  }

  private static BufferedImage read(Path png) throws IOException {
    BufferedImage image = ImageIO.read(png.toFile());
    assertThat(image).as("%s is a PNG", png).isNotNull();
    return image;
  }

  /** How many pixels of {@code colour} the picture has. */
  private static long pixels(BufferedImage image, Color colour) {
    long n = 0;
    for (int y = 0; y < image.getHeight(); y++) {
      for (int x = 0; x < image.getWidth(); x++) {
        if ((image.getRGB(x, y) & 0xFFFFFF) == (colour.getRGB() & 0xFFFFFF)) {
          n++;
        }
      }
    }
    return n;
  }

  /** A shade of the filtered-out row's orange over white. */
  private static boolean isOrange(Color c) {
    return c.getRed() > 240 && c.getGreen() > c.getBlue() + 40 && c.getGreen() < 240;
  }

  @Test
  void eachKindOfStepHasARowAndRequestsAndAppliedAlways() {
    List<Step> steps =
        List.of(
            new Step(0, "energy", Kind.FILTER, ""),
            new Step(0.01, "energy", Kind.SENT, ""),
            new Step(0.01, "energy", Kind.NOTE, "a note"));

    assertThat(LoopPicture.rows(steps))
        .extracting(LoopPicture.Row::name)
        .containsExactly(
            "notifications sent", "filter set", "requested", "applied", "meta's notes");
  }

  @Test
  void severalRobotsHaveTheirRowsEachInTheSameOrder() {
    List<Step> steps =
        List.of(
            new Step(0, "atom-1", Kind.FILTER, ""),
            new Step(0, "atom-0", Kind.FILTER, ""),
            new Step(1, "atom-0", Kind.REFUSED, "unknown schema"));

    assertThat(LoopPicture.rows(steps))
        .extracting(LoopPicture.Row::name)
        .containsExactly(
            "atom-1 · filter set",
            "atom-1 · requested",
            "atom-1 · applied",
            "atom-1 · refused",
            "atom-0 · filter set",
            "atom-0 · requested",
            "atom-0 · applied",
            "atom-0 · refused");
  }

  @Test
  void aLoopIsDrawnWithItsNotificationsAndItsRequestLinkedToItsApplication() throws IOException {
    List<Step> steps = loop("energy");
    Path linked = dir.resolve("reflective-loop.png");
    LoopPicture.write(
        "energy: the reflective loop",
        steps,
        List.of(new Link("energy", 9, 9.01, true)),
        15,
        linked);
    Path unlinked = dir.resolve("unlinked.png");
    LoopPicture.write("energy: the reflective loop", steps, List.of(), 15, unlinked);

    BufferedImage image = read(linked);
    assertThat(image.getWidth()).isEqualTo(1100);
    Color link = new Color(0x2CA02C).darker();
    assertThat(pixels(image, link)).as("the line from request to application").isPositive();
    assertThat(pixels(read(unlinked), link)).isZero();
    // Ticks of the filtered-out row: translucent, darker where they crowd, so many shades.
    long shades =
        java.util.stream.IntStream.range(0, image.getWidth() * image.getHeight())
            .map(i -> image.getRGB(i % image.getWidth(), i / image.getWidth()))
            .filter(rgb -> isOrange(new Color(rgb)))
            .distinct()
            .count();
    assertThat(shades).isGreaterThan(1);
  }

  @Test
  void aRefusedRequestIsLinkedToItsRefusal() throws IOException {
    List<Step> steps =
        List.of(
            new Step(1, "r", Kind.REQUESTED, "addSchema climb"),
            new Step(1.02, "r", Kind.REFUSED, "+2 cycles (20 ms): unknown schema 'climb'"));
    Path png = dir.resolve("refused.png");
    LoopPicture.write("refused", steps, List.of(new Link("r", 1, 1.02, false)), 2, png);

    assertThat(pixels(read(png), new Color(0xD62728).darker())).isPositive();
  }

  @Test
  void badInputIsRefusedWithTheValue() {
    Path png = dir.resolve("l.png");
    List<Step> steps = List.of(new Step(0, "r", Kind.SENT, ""));
    assertThatThrownBy(() -> LoopPicture.write("t", List.of(), List.of(), 1, png))
        .hasMessageContaining("at least one step");
    assertThatThrownBy(() -> LoopPicture.write("t", steps, List.of(), 0, png))
        .hasMessageContaining("not 0.0");
    assertThatThrownBy(
            () -> LoopPicture.write("t", steps, List.of(new Link("q", 0, 1, true)), 1, png))
        .hasMessageContaining("'q'");
    assertThatThrownBy(() -> LoopPicture.write("t", steps, List.of(), 1, dir.resolve("l.svg")))
        .hasMessageContaining("l.svg");
    assertThatThrownBy(() -> new Step(-0.5, "r", Kind.SENT, "")).hasMessageContaining("-0.5");
    assertThatThrownBy(() -> new Link("r", 0, Double.NaN, true)).hasMessageContaining("NaN");
  }
}

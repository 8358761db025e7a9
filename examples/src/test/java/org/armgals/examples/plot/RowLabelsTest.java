package org.armgals.examples.plot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.tuple;

import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.List;
import org.armgals.examples.plot.RowLabels.Mark;
import org.armgals.examples.plot.RowLabels.Placed;
import org.junit.jupiter.api.Test;

/** Labels of a row never overlap: close ones go below, or are written as one. */
class RowLabelsTest {
  private static final FontMetrics METRICS;

  static {
    Picture.headless();
    Graphics2D g = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB).createGraphics();
    METRICS = g.getFontMetrics(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
    g.dispose();
  }

  private static void assertNoOverlap(List<Placed> placed) {
    for (int lane = 0; lane < 2; lane++) {
      double end = Double.NEGATIVE_INFINITY;
      for (Placed p : placed) {
        if (p.lane() == lane) {
          assertThat(p.x())
              .as("'%s' starts after the label before it", p.text())
              .isGreaterThan(end);
          end = p.x() + METRICS.stringWidth(p.text());
        }
      }
    }
  }

  @Test
  void labelsFarApartAreWrittenBesideTheirMarksAbove() {
    List<Placed> placed =
        RowLabels.place(
            List.of(new Mark(100, "first"), new Mark(500, "second")), 0, 1000, true, METRICS);

    assertThat(placed)
        .containsExactly(
            new Placed(100 + RowLabels.GAP, 0, "first"),
            new Placed(500 + RowLabels.GAP, 0, "second"));
  }

  @Test
  void aLabelThatWouldOverlapGoesBelowThenMarksJoinTheNearestLabelCounted() {
    List<Placed> placed =
        RowLabels.place(
            List.of(
                new Mark(100, "addSchema lift-front"),
                new Mark(101, "removeSchema cruise"),
                new Mark(102, "+1 cycle (10 ms)"),
                new Mark(103, "+1 cycle (10 ms)")),
            0,
            1000,
            true,
            METRICS);

    assertThat(placed)
        .extracting(Placed::lane, Placed::text)
        .containsExactly(
            tuple(0, "addSchema lift-front"), tuple(1, "removeSchema cruise; +1 cycle (10 ms) ×2"));
    assertNoOverlap(placed);
  }

  @Test
  void marksSayingWhatTheirLabelSaysJoinItAndARowWithoutSpaceBelowJoinsTheRest() {
    List<Mark> marks =
        List.of(
            new Mark(100, "+2 cycles (20 ms)"),
            new Mark(100, "+2 cycles (20 ms)"),
            new Mark(100, "+1 cycle (10 ms)"));

    assertThat(RowLabels.place(marks, 0, 1000, true, METRICS))
        .extracting(Placed::lane, Placed::text)
        .containsExactly(tuple(0, "+2 cycles (20 ms) ×2"), tuple(1, "+1 cycle (10 ms)"));
    assertThat(RowLabels.place(marks, 0, 1000, false, METRICS))
        .extracting(Placed::lane, Placed::text)
        .containsExactly(tuple(0, "+2 cycles (20 ms) ×2; +1 cycle (10 ms)"));
  }

  @Test
  void aLabelPastTheRightEndEndsThereAndOneTooLongIsCut() {
    String note = "the saving gait draws 0.45 W, 11.52 J left: about 25 s more ".repeat(4);
    List<Placed> placed =
        RowLabels.place(
            List.of(new Mark(390, "kind = 'threshold'"), new Mark(10, note)),
            0,
            400,
            true,
            METRICS);

    assertThat(placed).hasSize(2);
    Placed cut = placed.get(0);
    assertThat(cut.text()).endsWith("…");
    assertThat(METRICS.stringWidth(cut.text())).isLessThanOrEqualTo(200);
    Placed last = placed.get(1);
    assertThat(last.text()).isEqualTo("kind = 'threshold'");
    assertThat(last.x() + METRICS.stringWidth(last.text())).isLessThanOrEqualTo(400);
    assertNoOverlap(placed);
  }

  @Test
  void manyMarksCloseTogetherNeverOverlap() {
    List<Mark> marks =
        java.util.stream.IntStream.range(0, 200)
            .mapToObj(i -> new Mark(i * 3.7, "request " + (i % 7)))
            .toList();

    List<Placed> placed = RowLabels.place(marks, 0, 800, true, METRICS);

    assertNoOverlap(placed);
    assertThat(placed)
        .allSatisfy(
            p -> assertThat(p.x() + METRICS.stringWidth(p.text())).isLessThanOrEqualTo(800));
    assertThat(String.join(" ", placed.stream().map(Placed::text).toList())).contains("more)");
  }
}

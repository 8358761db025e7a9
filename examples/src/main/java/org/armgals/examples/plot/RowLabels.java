package org.armgals.examples.plot;

import java.awt.FontMetrics;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Lays out the labels of one row of a time line so that none overlaps another. A label starts just
 * right of its mark (or ends at the row's right end, if it would go past it), above the row; where
 * the space above is taken, below it; where both are, the mark's text joins the label it falls
 * under, which then says each distinct text once, with its count ({@code "+1 cycle ×4; +2
 * cycles"}), as far as it fits, and how many more it leaves out ({@code "(+3 more)"}). A label is
 * at most half the row long.
 */
final class RowLabels {
  /** The space between a mark and its label, and between two labels, in pixels. */
  static final double GAP = 6;

  private RowLabels() {}

  /** A labelled mark at {@code x} pixels. */
  record Mark(double x, String text) {}

  /**
   * A label to write with its left end at {@code x} pixels, above the row (lane 0) or below it
   * (lane 1).
   */
  record Placed(double x, int lane, String text) {}

  /**
   * The labels of {@code marks}, in a row from {@code left} to {@code right} pixels, below the row
   * too if {@code below}.
   */
  static List<Placed> place(
      List<Mark> marks, double left, double right, boolean below, FontMetrics metrics) {
    List<Mark> sorted = new ArrayList<>(marks);
    sorted.sort(Comparator.comparingDouble(Mark::x));
    double longest = (right - left) / 2;
    List<Group> groups = new ArrayList<>();
    double[] ends = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
    Group[] last = new Group[2];
    for (Mark m : sorted) {
      int latest = last[1] != null && last[0] != null && last[1].x > last[0].x ? 1 : 0;
      int lane;
      if (m.x() >= ends[0]) {
        lane = 0;
      } else if (last[latest].texts.contains(m.text())) {
        lane = -1; // the label it falls under says it already: one more
      } else {
        lane = below && m.x() >= ends[1] ? 1 : -1;
      }
      if (lane >= 0) {
        Group g = new Group(m.x(), lane, ends[lane]);
        groups.add(g);
        last[lane] = g;
      } else {
        lane = latest;
      }
      Group g = last[lane];
      g.texts.add(m.text());
      g.layout(left, right, longest, metrics);
      ends[lane] = g.end(metrics);
    }
    return groups.stream()
        .filter(g -> !g.text.isEmpty())
        .map(g -> new Placed(g.at, g.lane, g.text))
        .toList();
  }

  /** The marks under one label. */
  private static final class Group {
    final double x;
    final int lane;
    final double previousEnd;
    final List<String> texts = new ArrayList<>();
    double at;
    String text = "";

    Group(double x, int lane, double previousEnd) {
      this.x = x;
      this.lane = lane;
      this.previousEnd = previousEnd;
    }

    void layout(double left, double right, double longest, FontMetrics metrics) {
      String full = label(texts, longest, metrics);
      double width = metrics.stringWidth(full);
      at = x + GAP;
      if (at + width > right) {
        at = right - width;
      }
      at = Math.max(Math.max(at, left), previousEnd + GAP);
      text = cut(full, right - at, metrics);
    }

    /** Where the next label of its lane may start: past its text and past its mark. */
    double end(FontMetrics metrics) {
      return Math.max(x, at + metrics.stringWidth(text)) + GAP;
    }
  }

  /**
   * One label for marks saying {@code texts}: each distinct text once, with its count, as many as
   * fit in {@code width} pixels, then how many marks it leaves out.
   */
  static String label(List<String> texts, double width, FontMetrics metrics) {
    Map<String, Integer> counts = new LinkedHashMap<>();
    texts.forEach(t -> counts.merge(t, 1, Integer::sum));
    StringBuilder label = new StringBuilder();
    int shown = 0;
    for (Map.Entry<String, Integer> e : counts.entrySet()) {
      String item =
          (label.isEmpty() ? "" : "; ")
              + e.getKey()
              + (e.getValue() > 1 ? " ×" + e.getValue() : "");
      int left = texts.size() - shown - e.getValue();
      String more = left > 0 ? " (+" + left + " more)" : "";
      if (metrics.stringWidth(label + item + more) > width) {
        break;
      }
      label.append(item);
      shown += e.getValue();
    }
    if (shown == texts.size()) {
      return label.toString();
    }
    String more = " (+" + (texts.size() - shown) + " more)";
    if (shown == 0) { // the first text is too long: cut it
      String first = texts.get(0);
      int firstCount = counts.get(first);
      String count = firstCount > 1 ? " ×" + firstCount : "";
      int left = texts.size() - firstCount;
      more = left > 0 ? " (+" + left + " more)" : "";
      return cut(first, width - metrics.stringWidth(count + more), metrics) + count + more;
    }
    return label + more;
  }

  /** {@code text}, cut with an ellipsis to at most {@code width} pixels; empty if nothing fits. */
  static String cut(String text, double width, FontMetrics metrics) {
    if (metrics.stringWidth(text) <= width) {
      return text;
    }
    for (int end = text.length() - 1; end > 0; end--) {
      String shorter = text.substring(0, end).stripTrailing() + "…";
      if (metrics.stringWidth(shorter) <= width) {
        return shorter;
      }
    }
    return "";
  }
}

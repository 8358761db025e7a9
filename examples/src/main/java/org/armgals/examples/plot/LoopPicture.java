package org.armgals.examples.plot;

import static java.util.Objects.requireNonNull;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.Marker;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * A run's reflective loop on a time line: simulated time across, one row per kind of step (and per
 * robot, when the meta level watches several), each request joined by a line to the moment it was
 * applied or refused, so that the loop's latency shows. Notifications, thousands in a run, are thin
 * translucent ticks: a row darkens where they crowd and stays white where none came. A step's label
 * (a filter's selector, a request, a note) is written beside it; labels that would overlap in a row
 * are written as one ({@code "+1 cycle ×4"}, {@code "addSchema climb (+3 more)"}).
 */
public final class LoopPicture {
  private static final int WIDTH = 1100;
  // A row holds its marks and a line of labels above and below them: 56 pixels a row leave some 50
  // once XChart has kept its margins.
  private static final int ROW_PIXELS = 56;
  private static final int MARK = 7;
  private static final Font LABEL = new Font(Font.SANS_SERIF, Font.PLAIN, 11);
  private static final Color TEXT = new Color(0x333333);
  private static final Color SEPARATOR = new Color(0x999999);

  static {
    Picture.headless();
  }

  private LoopPicture() {}

  /** A kind of step of the loop: one row of the picture. */
  public enum Kind {
    /** A robot sent its meta a notification. */
    SENT("notifications sent", new Color(0x7F7F7F), false),
    /** The meta received a notification and it passed the meta's filter. */
    PASSED("received, passed filter", new Color(0x17BECF), false),
    /** The meta received a notification and its filter dropped it. */
    FILTERED_OUT("received, filtered out", new Color(0xFF7F0E), false),
    /** The meta set its filter on a robot (at 0 s: the filter it started with). */
    FILTER("filter set", new Color(0x9467BD), false),
    /** The meta sent a robot an adaptation request. */
    REQUESTED("requested", new Color(0x1F77B4), true),
    /** The meta's damping held a request back. */
    HELD_BACK("held back by damping", new Color(0xBCBD22), false),
    /** The robot applied a request at its adaptation point. */
    APPLIED("applied", new Color(0x2CA02C), true),
    /** The robot refused a request. */
    REFUSED("refused", new Color(0xD62728), false),
    /** A note of the meta. */
    NOTE("meta's notes", new Color(0x8C564B), false),
    /** The robot went on without waiting for its meta. */
    FREE("running free", new Color(0xE377C2), false),
    /** The robot lost its meta. */
    META_LOST("meta lost", new Color(0x000000), false);

    private final String title;
    private final Color colour;
    private final boolean always;

    Kind(String title, Color colour, boolean always) {
      this.title = title;
      this.colour = colour;
      this.always = always;
    }

    /** The row's name on the picture. */
    public String title() {
      return title;
    }

    /** Notifications: many, drawn as thin translucent ticks. */
    boolean dense() {
      return this == SENT || this == PASSED || this == FILTERED_OUT;
    }
  }

  /**
   * One step of the loop.
   *
   * @param seconds when, in simulated seconds from the start of the run
   * @param robot the robot it is of
   * @param kind its kind: its row
   * @param label written beside it; empty for none
   */
  public record Step(double seconds, String robot, Kind kind, String label) {

    /** Checks the time and that nothing is missing. */
    public Step {
      requireNonNull(robot, "robot");
      requireNonNull(kind, "kind");
      requireNonNull(label, "label");
      checkTime(seconds, "step");
    }
  }

  /**
   * A request of {@code robot} decided at {@code requested} and applied (or refused) at {@code
   * answered}: a line from its mark on the requested row to its mark on the applied (or refused)
   * row.
   */
  public record Link(String robot, double requested, double answered, boolean applied) {

    /** Checks the times. */
    public Link {
      requireNonNull(robot, "robot");
      checkTime(requested, "request");
      checkTime(answered, "answer");
    }
  }

  /**
   * The rows of a picture of {@code steps}, top to bottom: for each robot in the order it first
   * comes in {@code steps}, a row for each kind of step {@code steps} has (for every robot, so that
   * the robots' rows line up), and rows of requests and of requests applied even without one: that
   * a meta level asked for nothing is an answer too.
   */
  static List<Row> rows(List<Step> steps) {
    Set<String> robots = new LinkedHashSet<>();
    Set<Kind> kinds = EnumSet.noneOf(Kind.class);
    for (Step s : steps) {
      robots.add(s.robot());
      kinds.add(s.kind());
    }
    List<Row> rows = new ArrayList<>();
    for (String robot : robots) {
      for (Kind kind : Kind.values()) {
        if (kind.always || kinds.contains(kind)) {
          rows.add(
              new Row(robot, kind, robots.size() > 1 ? robot + " · " + kind.title : kind.title));
        }
      }
    }
    return rows;
  }

  /** A row of the picture and the name it shows. */
  record Row(String robot, Kind kind, String name) {}

  /**
   * Draws {@code steps} and {@code links} over {@code [0, endSeconds]} (further if a step is later)
   * and writes the picture to {@code png} and as SVG beside it.
   *
   * @throws IllegalArgumentException if there is no step, if {@code endSeconds} is not after 0, or
   *     if a link's robot has no step
   */
  public static void write(
      String title, List<Step> steps, List<Link> links, double endSeconds, Path png) {
    requireNonNull(title, "title");
    requireNonNull(steps, "steps");
    requireNonNull(links, "links");
    requireNonNull(png, "png");
    if (steps.isEmpty()) {
      throw new IllegalArgumentException("a picture of the loop needs at least one step");
    }
    if (!(endSeconds > 0) || Double.isInfinite(endSeconds)) {
      throw new IllegalArgumentException("a time line must end after 0 s, not " + endSeconds);
    }
    Picture.checkPng(png, "picture");
    List<Row> rows = rows(steps);
    Map<String, Integer> index = new LinkedHashMap<>();
    for (int i = 0; i < rows.size(); i++) {
      index.put(key(rows.get(i).robot(), rows.get(i).kind()), i);
    }
    for (Link l : links) {
      if (!index.containsKey(key(l.robot(), Kind.REQUESTED))) {
        throw new IllegalArgumentException("link of robot '" + l.robot() + "', which has no step");
      }
    }
    double end = endSeconds;
    for (Step s : steps) {
      end = Math.max(end, s.seconds());
    }
    XYChart chart = chart(title, rows, end);
    addMarks(chart, rows, steps, index);
    int height = chart.getHeight();
    double last = end;
    Picture.write(
        WIDTH,
        height,
        g -> {
          chart.paint(g, WIDTH, height);
          Frame frame = new Frame(chart, rows.size(), last);
          separators(g, frame, rows);
          for (Link l : links) {
            link(g, frame, l, index);
          }
          labels(g, frame, rows, steps, index);
        },
        png,
        "picture");
  }

  private static void checkTime(double seconds, String what) {
    if (!Double.isFinite(seconds) || seconds < 0) {
      throw new IllegalArgumentException("a " + what + "'s time must be >= 0 s, not " + seconds);
    }
  }

  private static String key(String robot, Kind kind) {
    return robot + "\n" + kind;
  }

  /** The y of row {@code i} (0 at the top) of {@code n}: the first row is the highest. */
  private static double y(int i, int n) {
    return n - i;
  }

  private static XYChart chart(String title, List<Row> rows, double end) {
    int n = rows.size();
    XYChart chart =
        new XYChartBuilder()
            .width(WIDTH)
            .height(Math.max(420, 150 + ROW_PIXELS * n))
            .title(title)
            .xAxisTitle("simulated time (s)")
            .yAxisTitle(
                rows.stream().map(Row::robot).distinct().count() > 1
                    ? "robot · step of the loop"
                    : "step of the loop")
            .build();
    var styler = chart.getStyler();
    styler.setAntiAlias(true);
    styler.setLegendVisible(false);
    styler.setMarkerSize(MARK);
    styler.setXAxisTickMarkSpacingHint(100);
    styler.setXAxisMin(0.0);
    styler.setXAxisMax(end);
    styler.setYAxisMin(0.5);
    styler.setYAxisMax(n + 0.5);
    // XChart draws a tick's label only if all are different: the rows' names, and the number
    // itself (never seen: off the axis) for any other tick.
    styler.setYAxisTickLabelsFormattingFunction(
        v -> {
          long r = Math.round(v);
          return Math.abs(v - r) < 1e-9 && r >= 1 && r <= n
              ? rows.get((int) (n - r)).name()
              : Double.toString(v);
        });
    // Values seen first on an axis that are not equally spaced, and out of sight: XChart puts the
    // ticks of an axis whose values are equally spaced on those values, one in so many (at 0.3 s
    // for notifications every 10 ms), and may loop for ever looking for labels that fit there.
    XYSeries frame =
        chart.addSeries("frame", new double[] {end, end / 2}, new double[] {0.75, 0.6});
    frame.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
    frame.setMarker(SeriesMarkers.NONE);
    // One tick a row: once laid out, a hint a little above a row's height in pixels makes XChart's
    // step between ticks 1 (its steps are 1, 2 or 5 times a power of ten, the least above the
    // hint).
    BitmapEncoder.getBufferedImage(chart);
    double row = Math.abs(chart.getScreenYFromChart(1) - chart.getScreenYFromChart(2));
    styler.setYAxisTickMarkSpacingHint((int) Math.ceil(row * 1.1));
    return chart;
  }

  private static void addMarks(
      XYChart chart, List<Row> rows, List<Step> steps, Map<String, Integer> index) {
    int n = rows.size();
    List<List<Step>> plain = new ArrayList<>();
    List<List<Step>> marked = new ArrayList<>();
    for (int i = 0; i < n; i++) {
      plain.add(new ArrayList<>());
      marked.add(new ArrayList<>());
    }
    for (Step s : steps) {
      int i = index.get(key(s.robot(), s.kind()));
      (s.kind().dense() && s.label().isEmpty() ? plain : marked).get(i).add(s);
    }
    for (int i = 0; i < n; i++) {
      Kind kind = rows.get(i).kind();
      series(chart, "row " + i, plain.get(i), y(i, n), new Tick(), translucent(kind.colour));
      // A notification worth a label stands out of its row's ticks.
      Color colour = kind.dense() ? Color.BLACK : kind.colour;
      series(chart, "row " + i + " marked", marked.get(i), y(i, n), SeriesMarkers.DIAMOND, colour);
    }
  }

  private static void series(
      XYChart chart, String name, List<Step> steps, double y, Marker marker, Color colour) {
    if (steps.isEmpty()) {
      return;
    }
    double[] xs = steps.stream().mapToDouble(Step::seconds).toArray();
    double[] ys = new double[xs.length];
    java.util.Arrays.fill(ys, y);
    XYSeries series = chart.addSeries(name, xs, ys);
    series.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
    series.setMarker(marker);
    series.setMarkerColor(colour);
  }

  private static Color translucent(Color c) {
    return new Color(c.getRed(), c.getGreen(), c.getBlue(), 130);
  }

  /** A notification: a thin vertical tick, so that thousands in a row read as a density. */
  private static final class Tick extends Marker {
    @Override
    public void paint(Graphics2D g, double x, double y, int size) {
      g.setStroke(new BasicStroke(1f));
      g.draw(new Line2D.Double(x, y - size, x, y + size));
    }
  }

  /** Where chart values fall on the picture, once the chart is painted. */
  private record Frame(XYChart chart, int rows, double end) {
    double x(double seconds) {
      return chart.getScreenXFromChart(seconds);
    }

    double y(int row) {
      return chart.getScreenYFromChart(LoopPicture.y(row, rows));
    }

    double rowPixels() {
      return rows > 1 ? Math.abs(y(1) - y(0)) : ROW_PIXELS;
    }

    double left() {
      return x(0);
    }

    double right() {
      return x(end);
    }
  }

  private static void separators(Graphics2D g, Frame frame, List<Row> rows) {
    g.setColor(SEPARATOR);
    g.setStroke(new BasicStroke(1f));
    for (int i = 1; i < rows.size(); i++) {
      if (!rows.get(i).robot().equals(rows.get(i - 1).robot())) {
        double y = (frame.y(i - 1) + frame.y(i)) / 2;
        g.draw(new Line2D.Double(frame.left(), y, frame.right(), y));
      }
    }
  }

  private static void link(Graphics2D g, Frame frame, Link l, Map<String, Integer> index) {
    Kind to = l.applied() ? Kind.APPLIED : Kind.REFUSED;
    Integer toRow = index.get(key(l.robot(), to));
    if (toRow == null) {
      return; // cannot happen: a row of applied is always there, one of refused once one is
    }
    double x0 = frame.x(l.requested());
    double y0 = frame.y(index.get(key(l.robot(), Kind.REQUESTED)));
    double x1 = frame.x(l.answered());
    double y1 = frame.y(toRow);
    g.setColor(to.colour.darker());
    g.setStroke(new BasicStroke(1.5f));
    g.draw(new Line2D.Double(x0, y0, x1, y1));
    double angle = Math.atan2(y1 - y0, x1 - x0);
    double back = MARK + 1; // the head ends at the mark's edge
    double tipX = x1 - back * Math.cos(angle);
    double tipY = y1 - back * Math.sin(angle);
    Path2D head = new Path2D.Double();
    head.moveTo(tipX, tipY);
    head.lineTo(tipX - 7 * Math.cos(angle - 0.4), tipY - 7 * Math.sin(angle - 0.4));
    head.lineTo(tipX - 7 * Math.cos(angle + 0.4), tipY - 7 * Math.sin(angle + 0.4));
    head.closePath();
    g.fill(head);
  }

  private static void labels(
      Graphics2D g, Frame frame, List<Row> rows, List<Step> steps, Map<String, Integer> index) {
    List<List<RowLabels.Mark>> byRow = new ArrayList<>();
    for (int i = 0; i < rows.size(); i++) {
      byRow.add(new ArrayList<>());
    }
    for (Step s : steps) {
      if (!s.label().isEmpty()) {
        byRow
            .get(index.get(key(s.robot(), s.kind())))
            .add(new RowLabels.Mark(frame.x(s.seconds()), s.label()));
      }
    }
    g.setFont(LABEL);
    g.setColor(TEXT);
    FontMetrics metrics = g.getFontMetrics();
    double clear = MARK + 2; // from the row's line to the nearest edge of a label
    for (int i = 0; i < rows.size(); i++) {
      // Not below the last row of a robot: the line between two robots' rows is there.
      boolean below = i + 1 == rows.size() || rows.get(i + 1).robot().equals(rows.get(i).robot());
      for (RowLabels.Placed p :
          RowLabels.place(byRow.get(i), frame.left(), frame.right(), below, metrics)) {
        double baseline =
            p.lane() == 0
                ? frame.y(i) - clear - metrics.getDescent()
                : frame.y(i) + clear + metrics.getAscent();
        g.drawString(p.text(), (float) p.x(), (float) baseline);
      }
    }
  }
}

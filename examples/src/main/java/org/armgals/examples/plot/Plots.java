package org.armgals.examples.plot;

import static java.util.Objects.requireNonNull;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.SeriesMarkers;

/** The plots of a run, each written as one PNG file. */
public final class Plots {
  private static final int WIDTH = 800;
  private static final int HEIGHT = 600;

  static {
    Png.headless();
  }

  private Plots() {}

  /**
   * The paths of one or more bodies seen from above, one line each, with equal scales on both axes
   * so that a turn looks like a turn.
   *
   * @param paths by name (the legend), the (x, y) positions in metres, in time order
   * @throws IllegalArgumentException if there is no path or a path is empty, naming it
   */
  public static void trajectory(Map<String, List<Point>> paths, Path png) {
    requireNonNull(paths, "paths");
    if (paths.isEmpty()) {
      throw new IllegalArgumentException("a trajectory plot needs at least one path");
    }
    XYChart chart = chart("Trajectory seen from above", "x (m)", "y (m)");
    double minX = Double.MAX_VALUE, maxX = -Double.MAX_VALUE;
    double minY = Double.MAX_VALUE, maxY = -Double.MAX_VALUE;
    for (Map.Entry<String, List<Point>> path : paths.entrySet()) {
      List<Point> points = path.getValue();
      if (points.isEmpty()) {
        throw new IllegalArgumentException("path '" + path.getKey() + "' has no point");
      }
      for (Point p : points) {
        minX = Math.min(minX, p.x());
        maxX = Math.max(maxX, p.x());
        minY = Math.min(minY, p.y());
        maxY = Math.max(maxY, p.y());
      }
      XYSeries series = chart.addSeries(path.getKey(), xs(points), ys(points));
      series.setMarker(SeriesMarkers.NONE);
    }
    // Equal scales: the larger extent sets both, centred on the paths, never zero-sized.
    double half = Math.max(Math.max(maxX - minX, maxY - minY) / 2 * 1.1, 0.05);
    double cx = (minX + maxX) / 2;
    double cy = (minY + maxY) / 2;
    chart.getStyler().setXAxisMin(cx - half).setXAxisMax(cx + half);
    chart
        .getStyler()
        .setYAxisMin(cy - half * HEIGHT / WIDTH)
        .setYAxisMax(cy + half * HEIGHT / WIDTH);
    write(chart, png);
  }

  /**
   * A quantity over time, such as the energy left.
   *
   * @param points (seconds, value), in time order
   * @throws IllegalArgumentException if there is no point
   */
  public static void series(String title, String yLabel, List<Point> points, Path png) {
    requireNonNull(title, "title");
    requireNonNull(yLabel, "yLabel");
    requireNonNull(points, "points");
    if (points.isEmpty()) {
      throw new IllegalArgumentException("plot '" + title + "' needs at least one point");
    }
    XYChart chart = chart(title, "time (s)", yLabel);
    chart.getStyler().setLegendVisible(false);
    chart.addSeries(yLabel, xs(points), ys(points)).setMarker(SeriesMarkers.NONE);
    write(chart, png);
  }

  /**
   * Moments on a time line, one row per kind (adaptations and their reasons), over {@code [0,
   * endSeconds]}. With no marker, the time line is drawn empty: that a run made no adaptation is an
   * answer too.
   */
  public static void timeline(String title, List<Marker> markers, double endSeconds, Path png) {
    requireNonNull(title, "title");
    requireNonNull(markers, "markers");
    if (!(endSeconds > 0) || Double.isInfinite(endSeconds)) {
      throw new IllegalArgumentException("a time line must end after 0 s, not " + endSeconds);
    }
    XYChart chart = chart(title, "time (s)", "");
    chart.getStyler().setYAxisTicksVisible(false).setXAxisMin(0.0).setXAxisMax(endSeconds);
    Map<String, List<Point>> rows = new LinkedHashMap<>();
    for (Marker m : markers) {
      int row = rows.containsKey(m.kind()) ? indexOf(rows, m.kind()) : rows.size();
      rows.computeIfAbsent(m.kind(), k -> new ArrayList<>()).add(new Point(m.seconds(), row + 1));
    }
    if (rows.isEmpty()) {
      chart
          .addSeries("no adaptation", new double[] {0}, new double[] {0})
          .setMarker(SeriesMarkers.NONE);
    }
    for (Map.Entry<String, List<Point>> row : rows.entrySet()) {
      XYSeries series = chart.addSeries(row.getKey(), xs(row.getValue()), ys(row.getValue()));
      series.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
      series.setMarker(SeriesMarkers.DIAMOND);
    }
    chart.getStyler().setYAxisMin(0.0).setYAxisMax(rows.size() + 1.0);
    write(chart, png);
  }

  private static int indexOf(Map<String, List<Point>> rows, String kind) {
    return List.copyOf(rows.keySet()).indexOf(kind);
  }

  private static XYChart chart(String title, String xLabel, String yLabel) {
    XYChart chart =
        new XYChartBuilder()
            .width(WIDTH)
            .height(HEIGHT)
            .title(title)
            .xAxisTitle(xLabel)
            .yAxisTitle(yLabel)
            .build();
    chart.getStyler().setAntiAlias(true);
    return chart;
  }

  private static double[] xs(List<Point> points) {
    return points.stream().mapToDouble(Point::x).toArray();
  }

  private static double[] ys(List<Point> points) {
    return points.stream().mapToDouble(Point::y).toArray();
  }

  private static void write(XYChart chart, Path png) {
    requireNonNull(png, "png");
    if (!png.getFileName().toString().endsWith(".png")) {
      throw new IllegalArgumentException("a plot is written to a .png file, not " + png);
    }
    Png.write(BitmapEncoder.getBufferedImage(chart), png, "plot");
  }
}

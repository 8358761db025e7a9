package org.armgals.examples.plot;

import static java.util.Objects.requireNonNull;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.Shape;
import java.awt.geom.AffineTransform;
import java.awt.geom.Rectangle2D;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/** The plots of a run, each written as a PNG file and as SVG beside it. */
public final class Plots {
  static final int WIDTH = 800;
  static final int HEIGHT = 600;
  private static final Color CLEAR = new Color(0, 0, 0, 0);

  static {
    Picture.headless();
  }

  private Plots() {}

  /**
   * The paths of one or more bodies seen from above, one line each, over the obstacles of {@code
   * scene} (in grey), with exactly as many pixels per metre on both axes, so that a turn looks like
   * a turn and a square like a square.
   *
   * @param paths by name (the legend), the (x, y) positions in metres, in time order
   * @throws IllegalArgumentException if there is no path or a path is empty, naming it
   */
  public static void trajectory(Map<String, List<Point>> paths, SceneView scene, Path png) {
    requireNonNull(paths, "paths");
    requireNonNull(scene, "scene");
    Picture.checkPng(png, "plot");
    if (paths.isEmpty()) {
      throw new IllegalArgumentException("a trajectory plot needs at least one path");
    }
    XYChart chart = chart("Trajectory seen from above", "x (m)", "y (m)");
    chart.getStyler().setChartBackgroundColor(CLEAR).setPlotBackgroundColor(CLEAR);
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
    double margin = Math.max(Math.max(maxX - minX, maxY - minY) * 0.05, 0.02);
    Rectangle2D world =
        equalScales(
            chart,
            new Rectangle2D.Double(
                minX - margin, minY - margin, maxX - minX + 2 * margin, maxY - minY + 2 * margin));
    Picture.write(
        WIDTH,
        HEIGHT,
        g -> {
          solids(g, chart, world, scene);
          chart.paint(g, WIDTH, HEIGHT);
        },
        png,
        "plot");
  }

  /**
   * Sets the axes of {@code chart} to hold {@code data} (x across, y up, metres) with as many
   * pixels per metre on both: the axis that would have more is widened, about the data's centre,
   * until it has as many. The plot's area shrinks or grows as the ticks' labels change, so this
   * lays the chart out again until both scales agree to 1 in 10⁴. Answers the world's rectangle the
   * axes show.
   */
  static Rectangle2D equalScales(XYChart chart, Rectangle2D data) {
    double x0 = data.getMinX(), x1 = data.getMaxX();
    double y0 = data.getMinY(), y1 = data.getMaxY();
    for (int i = 0; i < 10; i++) {
      chart.getStyler().setXAxisMin(x0).setXAxisMax(x1).setYAxisMin(y0).setYAxisMax(y1);
      BitmapEncoder.getBufferedImage(chart); // lays it out
      double perX =
          Math.abs(chart.getScreenXFromChart(x1) - chart.getScreenXFromChart(x0)) / (x1 - x0);
      double perY =
          Math.abs(chart.getScreenYFromChart(y1) - chart.getScreenYFromChart(y0)) / (y1 - y0);
      if (Math.abs(perX / perY - 1) < 1e-4) {
        break;
      }
      double per = Math.min(perX, perY);
      double halfX = (x1 - x0) * perX / per / 2;
      double halfY = (y1 - y0) * perY / per / 2;
      double cx = (x0 + x1) / 2;
      double cy = (y0 + y1) / 2;
      x0 = cx - halfX;
      x1 = cx + halfX;
      y0 = cy - halfY;
      y1 = cy + halfY;
    }
    return new Rectangle2D.Double(x0, y0, x1 - x0, y1 - y0);
  }

  /** The obstacles of {@code scene} seen from above, on the plot's area of {@code chart}. */
  private static void solids(Graphics2D g, XYChart chart, Rectangle2D world, SceneView scene) {
    double left = chart.getScreenXFromChart(world.getMinX());
    double right = chart.getScreenXFromChart(world.getMaxX());
    double bottom = chart.getScreenYFromChart(world.getMinY());
    double top = chart.getScreenYFromChart(world.getMaxY());
    AffineTransform t = new AffineTransform();
    t.translate(left, bottom);
    t.scale((right - left) / world.getWidth(), (top - bottom) / world.getHeight());
    t.translate(-world.getMinX(), -world.getMinY());
    Shape clip = g.getClip();
    g.clip(new Rectangle2D.Double(left, top, right - left, bottom - top));
    for (SceneView.Solid solid : scene.solids()) {
      for (Shape s : solid.projected(0, 1)) {
        Shape onPlot = t.createTransformedShape(s);
        g.setColor(MoleculePicture.SOLID);
        g.fill(onPlot);
        g.setColor(MoleculePicture.SOLID_EDGE);
        g.draw(onPlot);
      }
    }
    g.setClip(clip);
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
    Picture.checkPng(png, "plot");
    if (points.isEmpty()) {
      throw new IllegalArgumentException("plot '" + title + "' needs at least one point");
    }
    XYChart chart = chart(title, "time (s)", yLabel);
    chart.getStyler().setLegendVisible(false);
    chart.addSeries(yLabel, xs(points), ys(points)).setMarker(SeriesMarkers.NONE);
    write(chart, png);
  }

  /** The title of a time line's vertical axis. */
  static final String TIMELINE_ROWS = "adaptation (one row per kind, see legend)";

  /**
   * Moments on a time line, one row per kind (adaptations and their reasons), over {@code [0,
   * endSeconds]}. With no marker, the time line is drawn empty: that a run made no adaptation is an
   * answer too.
   */
  public static void timeline(String title, List<Marker> markers, double endSeconds, Path png) {
    requireNonNull(title, "title");
    requireNonNull(markers, "markers");
    Picture.checkPng(png, "plot");
    if (!(endSeconds > 0) || Double.isInfinite(endSeconds)) {
      throw new IllegalArgumentException("a time line must end after 0 s, not " + endSeconds);
    }
    XYChart chart = chart(title, "time (s)", TIMELINE_ROWS);
    chart.getStyler().setYAxisTicksVisible(false).setXAxisMin(0.0).setXAxisMax(endSeconds);
    // Below the plot: an adaptation's name is long, and beside the plot it would squeeze it.
    chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideS);
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
    // Never ".05": a leading zero, and as many decimals as a tick needs.
    chart.getStyler().setXAxisDecimalPattern("0.###").setYAxisDecimalPattern("0.###");
    return chart;
  }

  private static double[] xs(List<Point> points) {
    return points.stream().mapToDouble(Point::x).toArray();
  }

  private static double[] ys(List<Point> points) {
    return points.stream().mapToDouble(Point::y).toArray();
  }

  private static void write(XYChart chart, Path png) {
    Picture.write(WIDTH, HEIGHT, g -> chart.paint(g, WIDTH, HEIGHT), png, "plot");
  }
}

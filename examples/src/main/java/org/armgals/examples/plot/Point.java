package org.armgals.examples.plot;

/**
 * A point of a plot.
 *
 * @param x abscissa (metres, or seconds for a time series)
 * @param y ordinate
 */
public record Point(double x, double y) {

  /** Refuses coordinates that cannot be drawn. */
  public Point {
    if (!Double.isFinite(x) || !Double.isFinite(y)) {
      throw new IllegalArgumentException("a point must be finite, not (" + x + ", " + y + ")");
    }
  }
}

package org.armgals.examples.plot;

import static java.util.Objects.requireNonNull;

import java.awt.Shape;
import java.awt.geom.Area;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Rectangle2D;
import java.util.ArrayList;
import java.util.List;

/**
 * The fixed things of a world as the pictures draw them, in metres in world coordinates (z up): the
 * ground, the plane z = 0, always there, and the solids on it or above it (steps, walls, pipes).
 *
 * @param solids the obstacles, drawn in light grey under the paths and the molecule
 */
public record SceneView(List<Solid> solids) {

  /** A world with the ground only. */
  public static final SceneView GROUND = new SceneView(List.of());

  /** Copies the list. */
  public SceneView {
    solids = List.copyOf(solids);
  }

  /** An obstacle. */
  public sealed interface Solid {

    /**
     * The solid projected on the plane of world axes {@code across} and {@code up} (0 for x, 1 for
     * y, 2 for z), in metres: the shapes a view along the third axis sees.
     */
    List<Shape> projected(int across, int up);
  }

  /**
   * A box with its faces along the world axes: a step, a wall.
   *
   * @param min its corner of least x, y and z
   * @param max its corner of greatest x, y and z
   */
  public record Block(AtomView.Vec min, AtomView.Vec max) implements Solid {

    /** Checks that {@code max} is beyond {@code min} on every axis. */
    public Block {
      requireNonNull(min, "min");
      requireNonNull(max, "max");
      if (!(max.x() > min.x() && max.y() > min.y() && max.z() > min.z())) {
        throw new IllegalArgumentException(
            "a block's max corner must be beyond its min corner on every axis, not "
                + min
                + " to "
                + max);
      }
    }

    @Override
    public List<Shape> projected(int across, int up) {
      double x = coordinate(min, across);
      double y = coordinate(min, up);
      return List.of(
          new Rectangle2D.Double(x, y, coordinate(max, across) - x, coordinate(max, up) - y));
    }
  }

  /**
   * A hollow pipe along a world axis.
   *
   * @param centre the centre of its axis
   * @param axis 0 for x, 1 for y, 2 for z
   * @param innerRadius the radius of the free space inside
   * @param outerRadius the radius of its outside, beyond {@code innerRadius}
   * @param length its length along its axis
   */
  public record Tube(
      AtomView.Vec centre, int axis, double innerRadius, double outerRadius, double length)
      implements Solid {

    /** Checks the axis and the sizes. */
    public Tube {
      requireNonNull(centre, "centre");
      if (axis < 0 || axis > 2) {
        throw new IllegalArgumentException("a tube's axis is 0 (x), 1 (y) or 2 (z), not " + axis);
      }
      if (!(innerRadius > 0 && outerRadius > innerRadius && length > 0)
          || Double.isInfinite(outerRadius)
          || Double.isInfinite(length)) {
        throw new IllegalArgumentException(
            "a tube needs 0 < innerRadius < outerRadius and length > 0, not "
                + innerRadius
                + ", "
                + outerRadius
                + ", "
                + length);
      }
    }

    @Override
    public List<Shape> projected(int across, int up) {
      double ca = coordinate(centre, across);
      double cu = coordinate(centre, up);
      double half = length / 2;
      double wall = outerRadius - innerRadius;
      List<Shape> shapes = new ArrayList<>(2);
      if (axis == across) { // two walls, above and below its axis
        shapes.add(new Rectangle2D.Double(ca - half, cu + innerRadius, length, wall));
        shapes.add(new Rectangle2D.Double(ca - half, cu - outerRadius, length, wall));
      } else if (axis == up) { // two walls, either side of its axis
        shapes.add(new Rectangle2D.Double(ca + innerRadius, cu - half, wall, length));
        shapes.add(new Rectangle2D.Double(ca - outerRadius, cu - half, wall, length));
      } else { // seen along its axis: a ring
        Area ring =
            new Area(
                new Ellipse2D.Double(
                    ca - outerRadius, cu - outerRadius, 2 * outerRadius, 2 * outerRadius));
        ring.subtract(
            new Area(
                new Ellipse2D.Double(
                    ca - innerRadius, cu - innerRadius, 2 * innerRadius, 2 * innerRadius)));
        shapes.add(ring);
      }
      return shapes;
    }
  }

  static double coordinate(AtomView.Vec v, int axis) {
    return switch (axis) {
      case 0 -> v.x();
      case 1 -> v.y();
      default -> v.z();
    };
  }
}

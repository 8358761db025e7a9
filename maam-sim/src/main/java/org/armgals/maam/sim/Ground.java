package org.armgals.maam.sim;

import java.util.ArrayList;
import java.util.List;
import org.ode4j.math.DMatrix3;
import org.ode4j.ode.DAABBC;
import org.ode4j.ode.DBox;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DPlane;
import org.ode4j.ode.DRotation;
import org.ode4j.ode.OdeHelper;

/**
 * What does not move: the ground (the plane z = 0) and the scene's obstacles, each geometry in no
 * space, with its bounding box kept as numbers (the engine recomputes the box of a geometry in no
 * space each time it is asked).
 */
final class Ground {

  private static final int PIPE_STAVES = 16;

  /**
   * The obstacles' boxes, then the plane: the order in which an atom's contacts with them are made
   * (see {@link BroadPhase}).
   */
  final List<DGeom> geoms = new ArrayList<>();

  /** Their bounding boxes, geometry i's at 6i (see {@link Boxes}). */
  private final double[] boxes;

  /** The plane's index in {@link #geoms}: the last. */
  final int plane;

  /**
   * The plane's unit normal and its distance from the origin along it, as the engine keeps them.
   */
  private final double normal0;

  private final double normal1;
  private final double normal2;
  private final double depth;

  Ground(List<Obstacle> obstacles) {
    for (Obstacle o : obstacles) {
      switch (o) {
        case Obstacle.Box b -> box(b.center(), b.size(), new DMatrix3().setIdentity());
        case Obstacle.Pipe p -> pipe(p);
      }
    }
    DPlane ground = OdeHelper.createPlane(null, 0, 0, 1, 0);
    ground.setData(GeomTag.WORLD);
    plane = geoms.size();
    geoms.add(ground);
    normal0 = ground.getNormal().get0();
    normal1 = ground.getNormal().get1();
    normal2 = ground.getNormal().get2();
    depth = ground.getDepth();
    boxes = new double[6 * geoms.size()];
    for (int i = 0; i < geoms.size(); i++) {
      Boxes.copy(geoms.get(i).getAABB(), boxes, 6 * i);
    }
  }

  private void box(Vec3 center, Vec3 size, DMatrix3 rotation) {
    DBox box = OdeHelper.createBox(null, size.x(), size.y(), size.z());
    box.setPosition(center.x(), center.y(), center.z());
    box.setRotation(rotation);
    box.setData(GeomTag.WORLD);
    geoms.add(box);
  }

  /** A pipe of flat staves around its axis: each stave a thin box, tangent to the inner radius. */
  private void pipe(Obstacle.Pipe p) {
    double mid = p.innerRadius() + p.wall() / 2;
    double width = 2 * (p.innerRadius() + p.wall()) * Math.tan(Math.PI / PIPE_STAVES) * 1.05;
    for (int i = 0; i < PIPE_STAVES; i++) {
      double phi = 2 * Math.PI * i / PIPE_STAVES;
      double u = Math.cos(phi) * mid;
      double v = Math.sin(phi) * mid;
      Vec3 c = p.center();
      DMatrix3 r = new DMatrix3();
      // A box with length along the pipe's axis, thickness along the radius, width tangent.
      switch (p.axis()) {
        case 'x' -> {
          DRotation.dRFromAxisAndAngle(r, 1, 0, 0, phi);
          box(new Vec3(c.x(), c.y() + u, c.z() + v), new Vec3(p.length(), p.wall(), width), r);
        }
        case 'y' -> {
          DRotation.dRFromAxisAndAngle(r, 0, 1, 0, -phi);
          box(new Vec3(c.x() + v, c.y(), c.z() + u), new Vec3(width, p.length(), p.wall()), r);
        }
        default -> {
          DRotation.dRFromAxisAndAngle(r, 0, 0, 1, phi);
          box(new Vec3(c.x() + u, c.y() + v, c.z()), new Vec3(p.wall(), width, p.length()), r);
        }
      }
    }
  }

  /** Whether geometry {@code i}'s box overlaps the box in {@code box} at {@code at}. */
  boolean overlaps(int i, double[] box, int at) {
    return Boxes.overlap(boxes, 6 * i, box, at);
  }

  /**
   * Where the ray at {@code at} in {@code rays} (laid out as in {@link AtomModel#rays}), {@code
   * range} long, meets the plane: its distance along the ray, or {@link Double#POSITIVE_INFINITY}
   * if it does not within its range. This is the engine's ray-plane collider
   * (DxRay.CollideRayPlane), step for step, so the distance is the engine's to the bit; it reads no
   * engine geometry.
   */
  double rayOnPlane(double[] rays, int at, double range) {
    double alpha = depth - (normal0 * rays[at] + normal1 * rays[at + 1] + normal2 * rays[at + 2]);
    int u = at + AtomModel.RAY_UNIT;
    double k = normal0 * rays[u] + normal1 * rays[u + 1] + normal2 * rays[u + 2];
    if (k == 0) {
      return Double.POSITIVE_INFINITY;
    }
    alpha = alpha / k;
    if (alpha < 0 || alpha > range) {
      return Double.POSITIVE_INFINITY;
    }
    return alpha;
  }

  /** Copies geometry {@code i}'s box into {@code to} at {@code at}. */
  void box(int i, double[] to, int at) {
    System.arraycopy(boxes, 6 * i, to, at, 6);
  }

  /** Whether the box in {@code box} at {@code at} overlaps any of the geometries' boxes. */
  boolean touches(double[] box, int at) {
    for (int i = 0; i < geoms.size(); i++) {
      if (overlaps(i, box, at)) {
        return true;
      }
    }
    return false;
  }

  /** Whether the engine's box {@code box} overlaps any of the geometries' boxes. */
  boolean touches(DAABBC box) {
    for (int i = 0; i < geoms.size(); i++) {
      int o = 6 * i;
      if (box.getMin0() <= boxes[o + 1]
          && boxes[o] <= box.getMax0()
          && box.getMin1() <= boxes[o + 3]
          && boxes[o + 2] <= box.getMax1()
          && box.getMin2() <= boxes[o + 5]
          && boxes[o + 4] <= box.getMax2()) {
        return true;
      }
    }
    return false;
  }

  void destroy() {
    for (DGeom g : geoms) {
      g.destroy();
    }
  }
}

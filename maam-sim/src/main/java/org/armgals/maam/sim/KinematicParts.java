package org.armgals.maam.sim;

import org.ode4j.math.DMatrix3C;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DGeom;

/**
 * The parts of an atom with kinematic legs, in no space: the legs' capsules are placed on the
 * kernel's body only when a collision needs them, and the order the engine's simple space would
 * have kept them in is kept here. The atom is rigid, so a box around the kernel as wide as the
 * atom's reach holds every part wherever the legs point.
 *
 * <p>Part 0 is the kernel, part 1 + l the leg of ordinal l, made and put on the kernel's body in
 * that order.
 */
final class KinematicParts implements Parts {

  private final DGeom[] geoms;

  private final KinematicLeg[] legs;
  private final DBody kernel;
  private final double kernelRadius;
  private final double reach;

  /** The order the engine's simple space would keep the parts in. */
  private final PartOrder order;

  /** For each leg, a box in the kernel's frame that holds it wherever it turns in its cone. */
  private final double[] coneBoxes;

  /** Those boxes in the world, as of the kernel's pose when {@link #reachesKnown} was set. */
  private final double[] reaches;

  /** The atom's box in the world, as of the same pose. */
  private final double[] box = new double[6];

  private boolean reachesKnown;

  KinematicParts(
      DBody kernel, DGeom sphere, double kernelRadius, KinematicLeg[] legs, double reach) {
    this.kernel = kernel;
    // A nanometre more, for rounding.
    this.kernelRadius = kernelRadius + 1e-9;
    this.legs = legs;
    // A micrometre more than the reach: the engine's boxes round the other way by far less.
    this.reach = reach + 1e-6;
    geoms = new DGeom[legs.length + 1];
    geoms[0] = sphere;
    for (int l = 0; l < legs.length; l++) {
      geoms[l + 1] = legs[l].capsule;
    }
    order = new PartOrder(geoms.length);
    coneBoxes = new double[6 * legs.length];
    reaches = new double[6 * legs.length];
    double[] box = new double[6];
    for (int l = 0; l < legs.length; l++) {
      legs[l].coneBox(box);
      System.arraycopy(box, 0, coneBoxes, 6 * l, 6);
    }
  }

  @Override
  public boolean bound(int i, double[] to) {
    int p = order.get(i);
    if (p > 0) {
      System.arraycopy(reaches(), 6 * (p - 1), to, 0, 6);
    } else {
      DVector3C c = kernel.getPosition();
      for (int axis = 0; axis < 3; axis++) {
        to[2 * axis] = c.get(axis) - kernelRadius;
        to[2 * axis + 1] = c.get(axis) + kernelRadius;
      }
    }
    return true;
  }

  @Override
  public boolean legMayTouch(LegModel leg, Ground ground) {
    double[] reaches = reaches();
    int bit = leg.bit;
    if ((groundKnown & bit) == 0) {
      // Asked each step of a resting atom with a turning leg: the answer holds while the kernel
      // does not move (the ground is its simulation's one, which does not move either).
      if (ground.touches(reaches, 6 * leg.leg.ordinal())) {
        groundTouched |= bit;
      }
      groundKnown |= bit;
    }
    return (groundTouched & bit) != 0;
  }

  /** A bit per leg: whether its cone box's overlap with the ground is known, and whether it is. */
  private int groundKnown;

  private int groundTouched;

  /**
   * The legs' cone boxes in the world: each box's centre placed by the kernel's pose, its half
   * sizes summed over the turned axes, and a nanometre more for rounding; and the atom's box. The
   * kernel of an atom at rest does not move, so they are worked out again only when it has.
   */
  private double[] reaches() {
    if (!reachesKnown) {
      DVector3C p = kernel.getPosition();
      DMatrix3C r = kernel.getRotation();
      for (int axis = 0; axis < 3; axis++) {
        box[2 * axis] = p.get(axis) - reach;
        box[2 * axis + 1] = p.get(axis) + reach;
      }
      for (int l = 0; l < legs.length; l++) {
        int o = 6 * l;
        double cx = (coneBoxes[o] + coneBoxes[o + 1]) / 2;
        double cy = (coneBoxes[o + 2] + coneBoxes[o + 3]) / 2;
        double cz = (coneBoxes[o + 4] + coneBoxes[o + 5]) / 2;
        double hx = (coneBoxes[o + 1] - coneBoxes[o]) / 2;
        double hy = (coneBoxes[o + 3] - coneBoxes[o + 2]) / 2;
        double hz = (coneBoxes[o + 5] - coneBoxes[o + 4]) / 2;
        for (int axis = 0; axis < 3; axis++) {
          double c = p.get(axis) + r.get(axis, 0) * cx + r.get(axis, 1) * cy + r.get(axis, 2) * cz;
          double h =
              Math.abs(r.get(axis, 0)) * hx
                  + Math.abs(r.get(axis, 1)) * hy
                  + Math.abs(r.get(axis, 2)) * hz
                  + 1e-9;
          reaches[o + 2 * axis] = c - h;
          reaches[o + 2 * axis + 1] = c + h;
        }
      }
      reachesKnown = true;
      groundKnown = 0;
      groundTouched = 0;
    }
    return reaches;
  }

  @Override
  public void clean() {
    order.clean();
  }

  @Override
  public void box(double[] to, int at) {
    reaches();
    System.arraycopy(box, 0, to, at, 6);
  }

  @Override
  public int count() {
    return geoms.length;
  }

  @Override
  public DGeom part(int i) {
    int p = order.get(i);
    if (p > 0) {
      legs[p - 1].place();
    }
    return geoms[p];
  }

  @Override
  public void readyForRays() {
    for (int i = 0; i < geoms.length; i++) {
      // part(i) places a leg's capsule; the box needs the pose, so both are worked out.
      part(i).getAABB();
    }
  }

  @Override
  public void readyForGround(Ground ground, double[] box, int at) {
    for (int g = 0; g < ground.geoms.size(); g++) {
      if (!ground.overlaps(g, box, at)) {
        continue;
      }
      double[] reaches = reaches();
      for (int l = 0; l < legs.length; l++) {
        if (ground.overlaps(g, reaches, 6 * l)) {
          legs[l].place();
          geoms[l + 1].getAABB();
        }
      }
    }
  }

  @Override
  public void moved(LegModel leg) {
    order.moved(leg.leg.ordinal() + 1);
    leg.rayInPlace = false;
  }

  @Override
  public void bodyMoved() {
    reachesKnown = false;
    for (KinematicLeg leg : legs) {
      leg.rayInPlace = false;
    }
    // The body marks its geometries from the last put on it, a leg's, to the first, the kernel.
    for (int p = geoms.length - 1; p >= 0; p--) {
      order.moved(p);
    }
  }

  @Override
  public void destroy() {
    for (DGeom g : geoms) {
      g.destroy();
    }
  }
}

package org.armgals.maam.sim;

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
  private final double reach;

  /** The order the engine's simple space would keep the parts in. */
  private final PartOrder order;

  KinematicParts(DBody kernel, DGeom sphere, KinematicLeg[] legs, double reach) {
    this.kernel = kernel;
    this.legs = legs;
    // A micrometre more than the reach: the engine's boxes round the other way by far less.
    this.reach = reach + 1e-6;
    geoms = new DGeom[legs.length + 1];
    geoms[0] = sphere;
    for (int l = 0; l < legs.length; l++) {
      geoms[l + 1] = legs[l].capsule;
    }
    order = new PartOrder(geoms.length);
  }

  @Override
  public void clean() {
    order.clean();
  }

  @Override
  public void box(double[] to, int at) {
    DVector3C p = kernel.getPosition();
    to[at] = p.get0() - reach;
    to[at + 1] = p.get0() + reach;
    to[at + 2] = p.get1() - reach;
    to[at + 3] = p.get1() + reach;
    to[at + 4] = p.get2() - reach;
    to[at + 5] = p.get2() + reach;
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
  public void moved(LegModel leg) {
    order.moved(leg.leg.ordinal() + 1);
  }

  @Override
  public void bodyMoved() {
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

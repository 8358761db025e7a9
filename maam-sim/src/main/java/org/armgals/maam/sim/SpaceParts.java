package org.armgals.maam.sim;

import org.ode4j.ode.DGeom;
import org.ode4j.ode.DSpace;

/**
 * Parts in a simple space of the engine's, which keeps their order: the jointed model's, whose
 * bodies all move every step.
 */
final class SpaceParts implements Parts {

  private final DSpace space;
  private final DGeom[] order;

  SpaceParts(DSpace space, int count) {
    this.space = space;
    this.order = new DGeom[count];
  }

  @Override
  public void clean() {
    space.cleanGeoms();
    int i = 0;
    for (DGeom g : space.getGeoms()) {
      order[i++] = g;
    }
  }

  @Override
  public void box(double[] to, int at) {
    Boxes.copy(space.getAABB(), to, at);
  }

  @Override
  public int count() {
    return order.length;
  }

  @Override
  public DGeom part(int i) {
    return order[i];
  }

  @Override
  public boolean bound(int i, double[] to) {
    return false;
  }

  @Override
  public boolean legMayTouch(LegModel leg, Ground ground) {
    return true;
  }

  @Override
  public void readyForRays() {
    // Cleaning the space worked out every part's box, and the pose with it; this only checks.
    for (DGeom g : order) {
      g.getAABB();
    }
  }

  @Override
  public void readyForGround(Ground ground, double[] box, int at) {
    // Cleaning the space worked out every part's box.
  }

  @Override
  public void moved(LegModel leg) {
    // The engine keeps the order.
  }

  @Override
  public void bodyMoved() {
    // The engine keeps the order.
  }

  @Override
  public void destroy() {
    space.destroy();
  }
}

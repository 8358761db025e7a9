package org.armgals.maam.sim;

import java.util.Arrays;
import org.armgals.maam.spi.Leg;
import org.jspecify.annotations.Nullable;
import org.ode4j.ode.DContactGeomBuffer;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DRay;
import org.ode4j.ode.OdeHelper;

/**
 * Casts atoms' proximity rays against what their boxes overlap, but their own atoms: one caster per
 * lane, each with its own scratch and contact buffer, so that lanes cast at once (decision 0075).
 *
 * <p>Casting an atom's rays writes only its own legs' proximities and this caster's fields. It
 * reads the other atoms' parts, the ground and the grid, and writes none of them, provided every
 * atom's parts were {@link Parts#readyForRays readied} (placed, their engine poses and boxes up to
 * date) since they last moved: then the engine's ray colliders, pure functions of the two
 * geometries' poses and sizes into the buffer they are given, find nothing left to work out. One
 * lane that casts and files alone may leave the parts lazy: the parts a ray needs are then placed
 * as it needs them, by the one thread that reads them.
 */
final class RayCaster {

  private final BroadPhase broadPhase;
  private final Ground ground;
  private final DContactGeomBuffer contacts = new DContactGeomBuffer(1);

  /** The atom whose rays are being cast. */
  private @Nullable AtomModel casting;

  /** Its rays' boxes, leg l's at 6l, and a box around them all. */
  private final double[] rayBoxes = new double[6 * Leg.values().length];

  private final double[] reachBox = new double[6];

  /** The ray being cast's box. */
  private final double[] rayBox = new double[6];

  /** A part's box that surely holds it, and its engine box. */
  private final double[] bound = new double[6];

  private final double[] partBox = new double[6];

  /** The other atoms whose boxes overlap {@link #reachBox}, in the order the grid gave them. */
  private int[] reachedAtoms = new int[8];

  private int reached;
  private final AtomGrid.AtomVisitor reach = this::reach;

  RayCaster(BroadPhase broadPhase, Ground ground) {
    this.broadPhase = broadPhase;
    this.ground = ground;
  }

  /**
   * Casts {@code atom}'s aimed rays. The grid is asked once, with a box around all of them, for the
   * other atoms they may reach; each ray then tries those its own box overlaps, the very atoms the
   * grid would give it (a ray keeps the nearest of its hits, so the order they are tried in does
   * not matter).
   */
  void cast(AtomModel atom) {
    LegModel[] legs = atom.legs;
    boolean any = false;
    for (int l = 0; l < legs.length; l++) {
      LegModel leg = legs[l];
      if (!leg.aimed) {
        continue;
      }
      Boxes.copy(leg.ray.getAABB(), rayBoxes, 6 * l);
      if (!any) {
        System.arraycopy(rayBoxes, 6 * l, reachBox, 0, 6);
        any = true;
      } else {
        for (int axis = 0; axis < 3; axis++) {
          reachBox[2 * axis] = Math.min(reachBox[2 * axis], rayBoxes[6 * l + 2 * axis]);
          reachBox[2 * axis + 1] = Math.max(reachBox[2 * axis + 1], rayBoxes[6 * l + 2 * axis + 1]);
        }
      }
    }
    if (!any) {
      return;
    }
    reached = 0;
    casting = atom;
    broadPhase.grid().forEachOverlapping(reachBox, reach);
    casting = null;
    for (int l = 0; l < legs.length; l++) {
      if (legs[l].aimed) {
        castRay(legs[l], 6 * l);
      }
    }
  }

  /** {@code leg}'s ray, its box at {@code at} in {@link #rayBoxes}. */
  private void castRay(LegModel leg, int at) {
    DRay ray = leg.ray;
    System.arraycopy(rayBoxes, at, rayBox, 0, 6);
    for (int g = 0; g < ground.geoms.size(); g++) {
      if (ground.overlaps(g, rayBox, 0)) {
        hit(leg, ray, ground.geoms.get(g));
      }
    }
    double range = leg.atom.params.proximityRange();
    double[] boxes = broadPhase.boxes();
    for (int k = 0; k < reached; k++) {
      int a = reachedAtoms[k];
      if (Boxes.overlap(boxes, 6 * a, rayBox, 0)
          && !Boxes.segmentMisses(boxes, 6 * a, leg.aim, range)) {
        castAtParts(leg, broadPhase.atom(a).parts, range);
      }
    }
  }

  /**
   * {@code leg}'s ray against each of {@code parts} whose box overlaps the ray's and that the
   * segment may hit, in the parts' order.
   */
  private void castAtParts(LegModel leg, Parts parts, double range) {
    for (int i = 0; i < parts.count(); i++) {
      if (parts.bound(i, bound)
          && (!Boxes.overlap(bound, 0, rayBox, 0)
              || Boxes.segmentMisses(bound, 0, leg.aim, range))) {
        continue;
      }
      DGeom g = parts.part(i);
      Boxes.copy(g.getAABB(), partBox, 0);
      if (Boxes.overlap(partBox, 0, rayBox, 0)) {
        hit(leg, g, leg.ray);
      }
    }
  }

  /**
   * The engine's collider on the ray and a geometry, in the order the near callback was given them
   * before (the depth is the same either way): the nearest hit is the leg's proximity.
   */
  private void hit(LegModel leg, DGeom o1, DGeom o2) {
    if (OdeHelper.collide(o1, o2, 1, contacts) > 0) {
      leg.proximity = Math.min(leg.proximity, contacts.get(0).depth);
    }
  }

  private void reach(int a) {
    if (broadPhase.atom(a) == casting) {
      return;
    }
    if (reached == reachedAtoms.length) {
      reachedAtoms = Arrays.copyOf(reachedAtoms, 2 * reached);
    }
    reachedAtoms[reached++] = a;
  }
}

package org.armgals.maam.sim;

import java.util.Arrays;
import org.jspecify.annotations.Nullable;
import org.ode4j.ode.DContactGeomBuffer;
import org.ode4j.ode.DGeom;
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

  /** A box around all the aimed rays of the atom being cast. */
  private final double[] reachBox = new double[6];

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
    int aimed = atom.aimed;
    if (aimed == 0) {
      return;
    }
    LegModel[] legs = atom.legs;
    double[] rays = atom.rays;
    boolean any = false;
    for (int l = 0; l < legs.length; l++) {
      if ((aimed & 1 << l) == 0) {
        continue;
      }
      int box = AtomModel.RAY * l + AtomModel.RAY_BOX;
      if (!any) {
        System.arraycopy(rays, box, reachBox, 0, 6);
        any = true;
      } else {
        for (int axis = 0; axis < 3; axis++) {
          reachBox[2 * axis] = Math.min(reachBox[2 * axis], rays[box + 2 * axis]);
          reachBox[2 * axis + 1] = Math.max(reachBox[2 * axis + 1], rays[box + 2 * axis + 1]);
        }
      }
    }
    reached = 0;
    casting = atom;
    broadPhase.grid().forEachOverlapping(reachBox, reach);
    casting = null;
    for (int l = 0; l < legs.length; l++) {
      if ((aimed & 1 << l) != 0) {
        castRay(legs[l], rays, AtomModel.RAY * l);
      }
    }
  }

  /**
   * {@code leg}'s ray, where it is aimed from and along at {@code at} in {@code rays} and its box
   * after them.
   */
  private void castRay(LegModel leg, double[] rays, int at) {
    int rayBox = at + AtomModel.RAY_BOX;
    double range = leg.atom.params.proximityRange();
    for (int g = 0; g < ground.geoms.size(); g++) {
      if (!ground.overlaps(g, rays, rayBox)) {
        continue;
      }
      if (g == ground.plane) {
        leg.proximity = Math.min(leg.proximity, ground.rayOnPlane(rays, at, range));
      } else {
        hit(leg, leg.engineRay(), ground.geoms.get(g));
      }
    }
    double[] boxes = broadPhase.boxes();
    for (int k = 0; k < reached; k++) {
      int a = reachedAtoms[k];
      if (Boxes.overlap(boxes, 6 * a, rays, rayBox)
          && !Boxes.segmentMisses(boxes, 6 * a, rays, at, range)) {
        castAtParts(leg, rays, at, broadPhase.atom(a).parts, range);
      }
    }
  }

  /**
   * {@code leg}'s ray (at {@code at} in {@code rays}) against each of {@code parts} whose box
   * overlaps the ray's and that the segment may hit, in the parts' order.
   */
  private void castAtParts(LegModel leg, double[] rays, int at, Parts parts, double range) {
    int rayBox = at + AtomModel.RAY_BOX;
    for (int i = 0; i < parts.count(); i++) {
      if (parts.bound(i, bound)
          && (!Boxes.overlap(bound, 0, rays, rayBox)
              || Boxes.segmentMisses(bound, 0, rays, at, range))) {
        continue;
      }
      DGeom g = parts.part(i);
      Boxes.copy(g.getAABB(), partBox, 0);
      if (Boxes.overlap(partBox, 0, rays, rayBox)) {
        hit(leg, g, leg.engineRay());
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

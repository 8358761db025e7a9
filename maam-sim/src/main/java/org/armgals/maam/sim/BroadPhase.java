package org.armgals.maam.sim;

import java.util.ArrayList;
import java.util.List;
import org.jspecify.annotations.Nullable;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DRay;

/**
 * Which pairs of geometries the narrow phase ({@link Physics}'s near callback) looks at: the parts
 * of atoms whose boxes overlap, found with an {@link AtomGrid}; an atom's parts and what of the
 * {@link Ground} they overlap; and, while sensing, rays and what they overlap (decision 0062).
 *
 * <p>The solver visits each body's contacts in the order they were made, so the pairs come in the
 * order the engine's hash space gave them wherever that order can be kept: each atom's pairs with
 * other atoms first, then with the obstacles, then with the ground, each with the atom's parts in
 * {@link Parts}' order. Only the order of an atom's pairs with other atoms, and with several
 * obstacles at once, is this class's own; an atom that touches only the ground and one obstacle
 * moves bit for bit as it did.
 */
final class BroadPhase {

  private final Ground ground;

  /** The atoms, in id order. */
  private final List<AtomModel> atoms = new ArrayList<>();

  /** The atoms' boxes, atom i's at 6i (see {@link Boxes}), as of the last {@link #clean()}. */
  private double[] boxes = new double[0];

  private final AtomGrid grid = new AtomGrid();
  private final double[] box = new double[6];
  private final double[] other = new double[6];
  private final DGeom.DNearCallback near;
  private final AtomGrid.PairVisitor pairs = this::pair;

  BroadPhase(Ground ground, DGeom.DNearCallback near) {
    this.ground = ground;
    this.near = near;
  }

  /** Adds an atom; atoms are added in id order. */
  void add(AtomModel atom) {
    atoms.add(atom);
  }

  /**
   * Calls the near callback on this step's pairs: atoms with atoms, then each atom with the
   * obstacles and the ground (unless it {@link #restsOnTheGround rests on them}).
   */
  void collide() {
    clean();
    grid.forEachPair(pairs);
    for (int i = 0; i < atoms.size(); i++) {
      AtomModel atom = atoms.get(i);
      atom.restsOnTheGround = !atom.still && restsOnTheGround(atom);
      for (LegModel leg : atom.legs.values()) {
        if (atom.still || atom.restsOnTheGround && !leg.movesOnItsCarrier()) {
          // Neither the part nor what it touched moved.
          leg.contact |= leg.touchingGround;
        } else {
          leg.touchingGround = false;
        }
      }
      if (atom.still || atom.restsOnTheGround) {
        // The solver would ignore its contacts with what does not move.
        continue;
      }
      for (int g = 0; g < ground.geoms.size(); g++) {
        if (ground.overlaps(g, boxes, 6 * i)) {
          ground.box(g, other, 0);
          collideParts(atom, ground.geoms.get(g), other);
        }
      }
    }
  }

  /** Two atoms whose boxes overlap: their parts, unless neither atom moves. */
  private void pair(int a, int b) {
    AtomModel atomA = atoms.get(a);
    AtomModel atomB = atoms.get(b);
    if (atomA.still && atomB.still) {
      // Nothing moves: the contacts would be those of the last step, which the solver ignores
      // between resting bodies; the tips keep the contact state they had.
      return;
    }
    Parts partsA = atomA.parts;
    Parts partsB = atomB.parts;
    for (int i = 0; i < partsA.count(); i++) {
      DGeom g = partsA.part(i);
      Boxes.copy(g.getAABB(), box, 0);
      for (int j = 0; j < partsB.count(); j++) {
        DGeom h = partsB.part(j);
        Boxes.copy(h.getAABB(), other, 0);
        if (Boxes.overlap(box, 0, other, 0)) {
          near.call(null, g, h);
        }
      }
    }
  }

  /**
   * The near callback on each part of {@code atom} whose box overlaps {@code with}'s ({@code
   * withBox}), in the parts' order: the engine's simple space's collide2.
   */
  private void collideParts(AtomModel atom, DGeom with, double[] withBox) {
    Parts parts = atom.parts;
    for (int i = 0; i < parts.count(); i++) {
      DGeom g = parts.part(i);
      Boxes.copy(g.getAABB(), box, 0);
      if (Boxes.overlap(box, 0, withBox, 0)) {
        near.call(null, g, with);
      }
    }
  }

  /**
   * Calls the near callback on the rays of {@code legs} (aimed) and what their boxes overlap, but
   * their own atoms: the sensing pass.
   */
  void castRays(List<LegModel> legs) {
    clean();
    for (LegModel leg : legs) {
      DRay ray = leg.ray;
      Boxes.copy(ray.getAABB(), rayBox, 0);
      for (int g = 0; g < ground.geoms.size(); g++) {
        if (ground.overlaps(g, rayBox, 0)) {
          near.call(null, ray, ground.geoms.get(g));
        }
      }
      casting = leg;
      grid.forEachOverlapping(rayBox, rayNear);
    }
  }

  /** The leg whose ray is being cast, and the ray's box. */
  private @Nullable LegModel casting;

  private final double[] rayBox = new double[6];
  private final AtomGrid.AtomVisitor rayNear = this::rayNear;

  private void rayNear(int a) {
    AtomModel atom = atoms.get(a);
    LegModel leg = casting;
    if (leg != null && atom != leg.atom) {
      collideParts(atom, leg.ray, rayBox);
    }
  }

  /** After the engine's step: the bodies it moved marked their parts. */
  void stepped() {
    for (AtomModel atom : atoms) {
      if (atom.kernel.isEnabled()) {
        atom.parts.bodyMoved();
      }
    }
  }

  /** Starts a pass: cleans every atom's parts, as the engine did, and files the atoms' boxes. */
  private void clean() {
    int n = atoms.size();
    if (boxes.length < 6 * n) {
      boxes = new double[6 * n];
    }
    for (int i = 0; i < n; i++) {
      Parts parts = atoms.get(i).parts;
      parts.clean();
      parts.box(boxes, 6 * i);
    }
    grid.rebuild(boxes, n);
  }

  /**
   * Whether every contact {@code atom} would have with the ground and the obstacles this step is
   * one the solver ignores, so that none need be made: its body rests and stays at rest through the
   * step, for no binding holds it and no contact made this step joins it to another body, and the
   * legs that turn (whose contacts would wake it) touch none of them, their boxes overlapping none.
   * A still atom's contacts are left out as well; this leaves out those of an atom at rest that
   * waves its legs in the air.
   */
  private boolean restsOnTheGround(AtomModel atom) {
    if (atom.kernel.isEnabled() || atom.touchedBody) {
      return false;
    }
    for (LegModel leg : atom.legs.values()) {
      if (leg.binding != null) {
        return false;
      }
      if (leg.movesOnItsCarrier()) {
        leg.bounds(box);
        if (ground.touches(box, 0)) {
          leg.place();
          Boxes.copy(leg.capsule.getAABB(), box, 0);
          if (ground.touches(box, 0)) {
            return false;
          }
        }
      }
    }
    return true;
  }

  void destroy() {
    for (AtomModel atom : atoms) {
      atom.parts.destroy();
      for (LegModel leg : atom.legs.values()) {
        leg.ray.destroy();
      }
    }
    ground.destroy();
  }
}

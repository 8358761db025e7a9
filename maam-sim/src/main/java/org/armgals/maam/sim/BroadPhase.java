package org.armgals.maam.sim;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.IntConsumer;
import org.armgals.maam.spi.Leg;
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
  private final double[] groundBox = new double[6];
  private final DGeom.DNearCallback near;
  private final AtomGrid.PairVisitor pairs = this::pair;

  BroadPhase(Ground ground, DGeom.DNearCallback near) {
    this.ground = ground;
    this.near = near;
  }

  /** Adds an atom; atoms are added in id order, each at its {@link AtomModel#index}. */
  void add(AtomModel atom) {
    if (atom.index != atoms.size()) {
      throw new IllegalArgumentException(
          "atom " + atom.id + " at index " + atom.index + ": expected index " + atoms.size());
    }
    atoms.add(atom);
    int n = atoms.size();
    boxes = Arrays.copyOf(boxes, 6 * n);
    quiet = Arrays.copyOf(quiet, n);
    joined = Arrays.copyOf(joined, n);
  }

  /**
   * Whether each atom's contacts with the ground and obstacles are left out this step unless
   * another body joins it ({@link #joined}): it is still, or it {@link #restsOnTheGround rests}.
   */
  private boolean[] quiet = new boolean[0];

  /** Whether a contact made this step joined each atom's body to another body. */
  private boolean[] joined = new boolean[0];

  /** A contact made this step joined {@code atom}'s body to another body, which may wake it. */
  void joined(AtomModel atom) {
    joined[atom.index] = true;
  }

  /**
   * Before a step's collisions, for each atom after its servos and its bindings: decides whether it
   * is still, starts the pass on its parts (the engine cleaned every space at the start of one),
   * files its box, and decides whether its contacts with the ground can be left out, as far as that
   * can be told before other atoms' contacts are made; its tips keep touching the ground where they
   * do. Done while the atom is at hand: with a thousand atoms, every pass over them reads them from
   * memory afresh.
   */
  void prepare(AtomModel atom) {
    int i = atom.index;
    atom.beforeCollisions();
    file(atom);
    joined[i] = false;
    boolean rests = !atom.still && restsOnTheGround(atom);
    quiet[i] = atom.still || rests;
    for (LegModel leg : atom.legs) {
      if (atom.still || rests && !leg.movesOnItsCarrier()) {
        // Neither the part nor what it touched moved.
        leg.contact |= leg.touchingGround;
      } else {
        leg.touchingGround = false;
      }
    }
  }

  /**
   * Calls the near callback on this step's pairs, every atom {@link #prepare prepared}: for each
   * atom in turn, its pairs with the atoms after it, then (as all its pairs with other atoms are
   * made) its pairs with the obstacles and the ground, unless they are left out.
   */
  void collide() {
    grid.rebuild(boxes, atoms.size());
    for (int i = 0; i < atoms.size(); i++) {
      grid.forEachPairOf(i, pairs);
      if (quiet[i] && !joined[i]) {
        // The solver would ignore its contacts with what does not move.
        continue;
      }
      AtomModel atom = atoms.get(i);
      if (atom.still) {
        continue;
      }
      if (quiet[i]) {
        // Another body touched it, and may wake it: its contacts with the ground count after all.
        for (LegModel leg : atom.legs) {
          leg.touchingGround = false;
        }
      }
      for (int g = 0; g < ground.geoms.size(); g++) {
        if (ground.overlaps(g, boxes, 6 * i)) {
          ground.box(g, groundBox, 0);
          collideParts(atom, ground.geoms.get(g), groundBox, null, 0);
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
      if (partsA.bound(i, box) && !Boxes.overlap(box, 0, boxes, 6 * b)) {
        continue;
      }
      DGeom g = partsA.part(i);
      Boxes.copy(g.getAABB(), box, 0);
      for (int j = 0; j < partsB.count(); j++) {
        if (partsB.bound(j, other) && !Boxes.overlap(other, 0, box, 0)) {
          continue;
        }
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
   * withBox}), in the parts' order: the engine's simple space's collide2. A ray ({@code aim} not
   * null) is not tried against parts its segment surely misses.
   */
  private void collideParts(
      AtomModel atom, DGeom with, double[] withBox, double @Nullable [] aim, double length) {
    Parts parts = atom.parts;
    for (int i = 0; i < parts.count(); i++) {
      if (parts.bound(i, other)
          && (!Boxes.overlap(other, 0, withBox, 0)
              || aim != null && Boxes.segmentMisses(other, 0, aim, length))) {
        continue;
      }
      DGeom g = parts.part(i);
      Boxes.copy(g.getAABB(), box, 0);
      if (Boxes.overlap(box, 0, withBox, 0)) {
        near.call(null, g, with);
      }
    }
  }

  /**
   * Calls the near callback on the {@link LegModel#aimed aimed} rays of {@code atoms}' legs and
   * what their boxes overlap, but their own atoms: the sensing pass.
   */
  void castRays(List<AtomModel> atoms) {
    clean();
    for (AtomModel atom : atoms) {
      castRays(atom);
    }
  }

  /**
   * Cleans {@code atom}'s parts and files its box: the start of a step's collisions ({@link
   * #prepare}) and of a sensing pass, where once every atom is filed {@link #castRays(List,
   * IntConsumer)} casts the rays.
   */
  void file(AtomModel atom) {
    atom.parts.clean();
    atom.parts.box(boxes, 6 * atom.index);
  }

  /**
   * As {@link #castRays(List)}, every atom {@link #file filed}, handing each atom's index to {@code
   * cast} as soon as its own rays are cast: casting a ray writes only its own leg's proximity, so
   * what the atom senses is then known, and can be read while the atom is at hand.
   */
  void castRays(List<AtomModel> atoms, IntConsumer cast) {
    grid.rebuild(boxes, atoms.size());
    for (int i = 0; i < atoms.size(); i++) {
      castRays(atoms.get(i));
      cast.accept(i);
    }
  }

  /**
   * Casts {@code atom}'s aimed rays. The grid is asked once, with a box around all of them, for the
   * other atoms they may reach; each ray then tries those its own box overlaps, the very atoms the
   * grid would give it (a ray keeps the nearest of its hits, so the order they are tried in does
   * not matter).
   */
  private void castRays(AtomModel atom) {
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
    grid.forEachOverlapping(reachBox, reach);
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
        near.call(null, ray, ground.geoms.get(g));
      }
    }
    double range = leg.atom.params.proximityRange();
    for (int k = 0; k < reached; k++) {
      int a = reachedAtoms[k];
      if (Boxes.overlap(boxes, 6 * a, rayBox, 0)
          && !Boxes.segmentMisses(boxes, 6 * a, leg.aim, range)) {
        collideParts(atoms.get(a), ray, rayBox, leg.aim, range);
      }
    }
  }

  /** The atom whose rays are being cast. */
  private @Nullable AtomModel casting;

  /** Its rays' boxes, leg l's at 6l, and a box around them all. */
  private final double[] rayBoxes = new double[6 * Leg.values().length];

  private final double[] reachBox = new double[6];

  /** The ray being cast's box. */
  private final double[] rayBox = new double[6];

  /** The other atoms whose boxes overlap {@link #reachBox}, in the grid's order. */
  private int[] reachedAtoms = new int[8];

  private int reached;
  private final AtomGrid.AtomVisitor reach = this::reach;

  private void reach(int a) {
    if (atoms.get(a) == casting) {
      return;
    }
    if (reached == reachedAtoms.length) {
      reachedAtoms = Arrays.copyOf(reachedAtoms, 2 * reached);
    }
    reachedAtoms[reached++] = a;
  }

  /** Starts the sensing pass: cleans every atom's parts and files their boxes. */
  private void clean() {
    for (AtomModel atom : atoms) {
      file(atom);
    }
    grid.rebuild(boxes, atoms.size());
  }

  /**
   * Whether every contact {@code atom} would have with the ground and the obstacles this step is
   * one the solver ignores, so that none need be made: its body rests and stays at rest through the
   * step, for no binding holds it and (unless a contact with another body {@link #joined joins} it)
   * nothing else wakes it, and the legs that turn (whose contacts would wake it) touch none of
   * them, their boxes overlapping none. A still atom's contacts are left out as well; this leaves
   * out those of an atom at rest that waves its legs in the air.
   */
  private boolean restsOnTheGround(AtomModel atom) {
    if (atom.kernel.isEnabled()) {
      return false;
    }
    for (LegModel leg : atom.legs) {
      if (leg.binding != null) {
        return false;
      }
      if (leg.movesOnItsCarrier()
          && atom.parts.legMayTouch(leg, ground)
          && ground.touches(placed(leg).getAABB())) {
        return false;
      }
    }
    return true;
  }

  private static DGeom placed(LegModel leg) {
    leg.place();
    return leg.capsule;
  }

  void destroy() {
    for (AtomModel atom : atoms) {
      atom.parts.destroy();
      for (LegModel leg : atom.legs) {
        leg.ray.destroy();
      }
    }
    ground.destroy();
  }
}

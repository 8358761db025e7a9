package org.armgals.maam.sim;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.ode4j.ode.DGeom;

/**
 * Which pairs of geometries the narrow phase ({@link Physics}'s near callback) looks at: the parts
 * of atoms whose boxes overlap, in the order an {@link AtomGrid} gives them, from lists kept over
 * steps ({@link NearPairs}); an atom's parts and what of the {@link Ground} they overlap; and,
 * while sensing, rays and what they overlap, through a {@link RayCaster} per lane (decisions 0062,
 * 0075, 0076).
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

  /** The pairs of atoms that may touch, without searching the grid each step (decision 0076). */
  private final NearPairs nearPairs = new NearPairs();

  /** Whether each step files every atom in the grid and searches it: for tests. */
  private boolean searchEveryStep;

  private final double[] box = new double[6];
  private final double[] other = new double[6];
  private final double[] groundBox = new double[6];
  private final DGeom.DNearCallback near;
  private final AtomGrid.PairVisitor pairs = this::pair;

  /** A ray caster per lane, lane k's at k. */
  private final RayCaster[] casters;

  /** Calls {@code near} on a step's pairs, and casts rays on {@code lanes} lanes (at least 1). */
  BroadPhase(Ground ground, DGeom.DNearCallback near, int lanes) {
    this.ground = ground;
    this.near = near;
    casters = new RayCaster[lanes];
    for (int k = 0; k < lanes; k++) {
      casters[k] = new RayCaster(this, ground);
    }
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
    if (!quiet[i]) {
      // Its parts will meet the ground in the collisions: placed here, on its lane, they are placed
      // where the collisions would place them, off the calling thread.
      atom.parts.readyForGround(ground, boxes, 6 * i);
    }
    // The legs whose tips keep touching the ground where they do: neither the part nor what it
    // touched moved.
    int keep = atom.still ? -1 : rests ? ~atom.turning : 0;
    atom.contacts |= atom.touchingGrounds & keep;
    atom.touchingGrounds &= keep;
  }

  /**
   * Calls the near callback on this step's pairs, every atom {@link #prepare prepared}: for each
   * atom in turn, its pairs with the atoms after it, then (as all its pairs with other atoms are
   * made) its pairs with the obstacles and the ground, unless they are left out. The pairs of atoms
   * come from the {@link NearPairs} lists in the grid's order, or, while a box is not finite, from
   * the grid, every box filed.
   */
  void collide() {
    boolean listed = !searchEveryStep && nearPairs.update(boxes, atoms.size());
    if (listed) {
      grid.fitCells(boxes, atoms.size());
    } else {
      grid.rebuild(boxes, atoms.size());
    }
    for (int i = 0; i < atoms.size(); i++) {
      if (listed) {
        nearPairs.forEachPairOf(i, boxes, grid, pairs);
      } else {
        grid.forEachPairOf(i, pairs);
      }
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
        atom.touchingGrounds = 0;
      }
      for (int g = 0; g < ground.geoms.size(); g++) {
        if (ground.overlaps(g, boxes, 6 * i)) {
          ground.box(g, groundBox, 0);
          collideParts(atom, ground.geoms.get(g), groundBox);
        }
      }
    }
  }

  /**
   * Searches the grid for each step's pairs, as before decision 0076: for the test that holds both
   * ways to the same run.
   */
  void searchEveryStep() {
    searchEveryStep = true;
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
   * withBox}), in the parts' order: the engine's simple space's collide2.
   */
  private void collideParts(AtomModel atom, DGeom with, double[] withBox) {
    Parts parts = atom.parts;
    for (int i = 0; i < parts.count(); i++) {
      if (parts.bound(i, other) && !Boxes.overlap(other, 0, withBox, 0)) {
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
   * Cleans {@code atom}'s parts and files its box: the start of a step's collisions ({@link
   * #prepare}) and of a sensing pass, where once every atom is filed and the grid {@link
   * #fileForRays rebuilt} the rays are cast.
   */
  void file(AtomModel atom) {
    atom.parts.clean();
    atom.parts.box(boxes, 6 * atom.index);
  }

  /**
   * After every atom is {@link #file filed} for a sensing pass: files their boxes in the grid the
   * rays ask.
   */
  void fileForRays() {
    grid.rebuild(boxes, atoms.size());
    grid.fileRows();
  }

  /**
   * Casts {@code atom}'s aimed rays with lane {@code lane}'s caster, every atom {@link #file filed}
   * and the grid {@link #fileForRays rebuilt}. On several lanes every atom is also {@link
   * Parts#readyForRays readied}: lanes cast at once, each with its own caster, and read what no
   * lane writes until the pass is over (see {@link RayCaster}); one lane may leave the parts lazy.
   */
  void castRays(int lane, AtomModel atom) {
    casters[lane].cast(atom);
  }

  /** The grid of the atoms' boxes as last rebuilt. */
  AtomGrid grid() {
    return grid;
  }

  /** The atoms' boxes, atom i's at 6i, as last filed. */
  double[] boxes() {
    return boxes;
  }

  /** The atom at {@code index}. */
  AtomModel atom(int index) {
    return atoms.get(index);
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
    LegModel[] legs = atom.legs;
    for (int l = 0; l < legs.length; l++) {
      int bit = 1 << l;
      if ((atom.bound & bit) != 0) {
        return false;
      }
      // The legs that turn are those that move on their carrier.
      if ((atom.turning & bit) != 0
          && atom.parts.legMayTouch(legs[l], ground)
          && ground.touches(placed(legs[l]).getAABB())) {
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
        leg.destroyRay();
      }
    }
    ground.destroy();
  }
}

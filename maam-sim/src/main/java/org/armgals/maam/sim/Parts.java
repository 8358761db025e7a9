package org.armgals.maam.sim;

import org.ode4j.ode.DGeom;

/**
 * An atom's collision geometry as the {@link BroadPhase} sees it: a bounding box, and its parts
 * (kernel and leg capsules) in the order the engine made their contacts in. The engine's simple
 * space keeps its geometries in the order they last moved in since it was last cleaned, and the
 * solver visits each body's contacts in the order they were made: the order is kept so that runs
 * repeat bit for bit as they did with the engine's spaces (decision 0062).
 */
sealed interface Parts permits SpaceParts, KinematicParts {

  /** Starts a collision or sensing pass: the engine cleaned every space at the start of one. */
  void clean();

  /** Writes a box that holds every part into {@code to} at {@code at} (see {@link Boxes}). */
  void box(double[] to, int at);

  /** The number of parts. */
  int count();

  /** Part {@code i} in contact order (after {@link #clean()}), placed where it is now. */
  DGeom part(int i);

  /**
   * Writes a box that surely holds part {@code i} (in contact order) into {@code to} at 0, found
   * without placing the part, and returns true; false if there is none cheaper than the part's own.
   */
  boolean bound(int i, double[] to);

  /**
   * Whether {@code leg}'s capsule may touch the ground or an obstacle, told from a box that holds
   * it without placing it; true when in doubt.
   */
  boolean legMayTouch(LegModel leg, Ground ground);

  /**
   * Places every part and brings its engine pose and box up to date, after {@link #clean()}: then,
   * until a part moves, asking for a part, its pose or its box writes nothing, and lanes may cast
   * rays at the parts at once (see {@link RayCaster}).
   */
  void readyForRays();

  /**
   * Places the parts whose boxes may overlap what of {@code ground} the atom's box ({@code box} at
   * {@code at}) overlaps, and works out their engine boxes: what the step's collisions with the
   * ground would do first, done while the atom is at hand and on its lane. The values are those the
   * collisions would work out.
   */
  void readyForGround(Ground ground, double[] box, int at);

  /** {@code leg}'s capsule moved on its body (its engine geometry would have been marked). */
  void moved(LegModel leg);

  /** The atom's body moved (the engine marks each of its geometries, in its own order). */
  void bodyMoved();

  void destroy();
}

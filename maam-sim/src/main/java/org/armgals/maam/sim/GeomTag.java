package org.armgals.maam.sim;

import org.jspecify.annotations.Nullable;

/**
 * What a collision geometry belongs to: an atom (the space of its parts), its kernel, a leg, a
 * leg's proximity ray, or the world.
 */
record GeomTag(Kind kind, @Nullable AtomModel atom, @Nullable LegModel leg) {

  enum Kind {
    WORLD,
    KERNEL,
    LEG,
    RAY
  }

  static final GeomTag WORLD = new GeomTag(Kind.WORLD, null, null);
}

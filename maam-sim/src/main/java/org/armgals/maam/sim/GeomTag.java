package org.armgals.maam.sim;

import org.jspecify.annotations.Nullable;

/**
 * What a collision geometry belongs to: an atom (the space of its parts), its kernel, a leg, or the
 * world. The legs' proximity rays have none: they never reach the near callback, a {@link
 * RayCaster} casts them.
 */
record GeomTag(Kind kind, @Nullable AtomModel atom, @Nullable LegModel leg) {

  enum Kind {
    WORLD,
    KERNEL,
    LEG
  }

  static final GeomTag WORLD = new GeomTag(Kind.WORLD, null, null);
}

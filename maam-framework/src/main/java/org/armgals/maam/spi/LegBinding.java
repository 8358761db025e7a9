package org.armgals.maam.spi;

import static java.util.Objects.requireNonNull;

/** What a leg tip is bound to: nothing, or the leg tip of a neighbour atom. */
public sealed interface LegBinding {

  /** The leg tip is free. */
  LegBinding FREE = new Free();

  /** Not bound. */
  record Free() implements LegBinding {}

  /**
   * Bound to leg {@code neighbourLeg} of the atom whose {@link Body#id} is {@code neighbour}.
   *
   * @param neighbour the neighbour's id
   * @param neighbourLeg the neighbour's leg holding this one
   */
  record Bound(String neighbour, Leg neighbourLeg) implements LegBinding {

    /** Checks for nulls. */
    public Bound {
      requireNonNull(neighbour, "neighbour");
      requireNonNull(neighbourLeg, "neighbourLeg");
    }
  }
}

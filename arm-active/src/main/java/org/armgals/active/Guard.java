package org.armgals.active;

/**
 * The guard of a request: whether the servant's current state lets the request run. Guards must be
 * side-effect free; they are evaluated by the receiving object, maybe several times.
 *
 * @param <S> the servant type
 */
@FunctionalInterface
public interface Guard<S> {
  /** Whether the request may run now. */
  boolean test(S servant);
}

package org.armgals.representation;

import static java.util.Objects.requireNonNull;

import org.jspecify.annotations.Nullable;

/**
 * What one application of a behavior did: the state before, the state after, the behavior's name
 * and its result ({@code null} when it has none, as for a transition).
 *
 * @param <S> the state type of the family
 */
public record Step<S extends State>(S before, S after, String behavior, @Nullable Object result) {

  /** Checks that every component but the result is present. */
  public Step {
    requireNonNull(before, "before");
    requireNonNull(after, "after");
    requireNonNull(behavior, "behavior");
  }

  /** Whether the step changed the state. */
  public boolean changed() {
    return !before.equals(after);
  }
}

package org.armgals.representation.sc;

import org.jspecify.annotations.Nullable;

/**
 * A named condition on a transition ({@code cond} in SCXML, which has no data model here). A guard
 * is a pure function of the configuration and the trigger's input, so that a model replaying the
 * transition decides as the entity did.
 */
@FunctionalInterface
public interface Guard {
  /** Whether the guarded transition is enabled in {@code configuration} with {@code input}. */
  boolean test(Configuration configuration, @Nullable Object input);
}

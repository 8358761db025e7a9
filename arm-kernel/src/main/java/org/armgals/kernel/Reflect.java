package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import org.jspecify.annotations.Nullable;

/**
 * The result a behavior returns to ask its entity's behavioral meta for a reflective computation:
 * the entity turns it into a {@link ReflectiveRequest}. Behaviors stay pure functions of a state
 * (they can be replayed on a model); asking the meta is what the entity does with their result.
 *
 * @param subject what to ask about
 * @param argument a simple value, or {@code null}
 */
public record Reflect(String subject, @Nullable Object argument) {

  /** Checks the subject. */
  public Reflect {
    requireNonNull(subject, "subject");
  }
}

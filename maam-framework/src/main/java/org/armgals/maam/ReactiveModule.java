package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.util.List;

/**
 * A named group of behavior modules inside a {@link Schema} (paper §5.4, {@code ReactiveModule}):
 * typically one reflex, a perceptor, a reactor and an actuator. It groups for reading and for
 * reports; the wiring is the schema's.
 *
 * @param name unique in its schema
 * @param modules at least one, in declaration order (the order ties are broken by)
 */
public record ReactiveModule(String name, List<BehaviorModule> modules) {

  /** Checks the name and copies the list. */
  public ReactiveModule {
    requireNonNull(name, "name");
    if (name.isBlank()) {
      throw new IllegalArgumentException("reactive module name '" + name + "': expected not blank");
    }
    modules = List.copyOf(modules);
    if (modules.isEmpty()) {
      throw new IllegalArgumentException(
          "reactive module '" + name + "' has no behavior module: expected at least one");
    }
  }

  /** A reactive module named {@code name} of {@code modules}. */
  public static ReactiveModule of(String name, BehaviorModule... modules) {
    return new ReactiveModule(name, List.of(modules));
  }
}

package org.armgals.representation.sc;

import static java.util.Objects.requireNonNull;

import java.util.List;

/** Checks of the names a statechart definition holds. */
final class ScNames {
  private ScNames() {}

  /** {@code name}, if it is a non-empty token without white space. */
  static String requireName(String name, String what) {
    requireNonNull(name, what);
    if (name.isEmpty()
        || !name.equals(name.strip())
        || name.chars().anyMatch(Character::isWhitespace)) {
      throw new IllegalArgumentException(
          what + " '" + name + "' is not a name; expected a non-empty token without white space");
    }
    return name;
  }

  /** An unmodifiable copy of {@code names}, each checked. */
  static List<String> requireNames(List<String> names, String what) {
    requireNonNull(names, what);
    for (String n : names) {
      requireName(n, what);
    }
    return List.copyOf(names);
  }
}

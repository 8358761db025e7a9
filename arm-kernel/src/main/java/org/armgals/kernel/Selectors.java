package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.Map;
import java.util.function.Predicate;

/** Compiles the selectors of behavioral metas' filters (JMS message-selector syntax). */
final class Selectors {
  private Selectors() {}

  /**
   * The filter {@code selector} stands for; a blank selector accepts everything.
   *
   * @throws IllegalArgumentException if it does not parse, naming it
   */
  static Predicate<Map<String, Object>> compile(String selector) {
    requireNonNull(selector, "selector");
    if (selector.isBlank()) {
      return p -> true;
    }
    throw new IllegalArgumentException("selectors are not available yet: '" + selector + "'");
  }
}

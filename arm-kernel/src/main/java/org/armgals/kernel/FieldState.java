package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.Map;
import org.armgals.representation.State;

/**
 * The state of a kernel entity in the kernel's own representation: named simple values (a
 * structural meta's name and behavior names, a behavioral meta's base entities). The kernel uses it
 * to describe itself, so that {@code basicBehavioralMeta} models the kernel entities like any
 * other.
 */
record FieldState(Map<String, Object> fields) implements State {

  static final FieldState EMPTY = new FieldState(Map.of());

  FieldState {
    fields = Map.copyOf(requireNonNull(fields, "fields"));
  }

  @Override
  public Map<String, Object> observe() {
    return fields;
  }
}

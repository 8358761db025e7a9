package org.armgals.active;

import static java.util.Objects.requireNonNull;

/**
 * The location-transparent name of an active object: the runtime that hosts it and its number
 * there. Addresses are values; they cross runtimes (and, with a distributed transport, JVMs).
 *
 * @param runtime the name of the hosting {@link ActiveRuntime}, never blank
 * @param id the object's number in that runtime, at least 1
 */
public record Address(String runtime, long id) {

  /** Checks the components. */
  public Address {
    requireNonNull(runtime, "runtime");
    if (runtime.isBlank()) {
      throw new IllegalArgumentException("runtime must not be blank, was '" + runtime + "'");
    }
    if (id < 1) {
      throw new IllegalArgumentException("id must be >= 1, was " + id);
    }
  }

  @Override
  public String toString() {
    return runtime + "#" + id;
  }
}

package org.armgals.maam;

import static java.util.Objects.requireNonNull;

/**
 * A named, typed input or output of a {@link BehaviorModule}. Two ports are the same port when both
 * name and type are equal, so a module may declare its ports as constants.
 *
 * @param name not blank
 * @param type the signals it carries
 * @param <S> the signal type
 */
public record Port<S extends Signal>(String name, Class<S> type) {

  /** Checks the name. */
  public Port {
    requireNonNull(name, "name");
    requireNonNull(type, "type");
    if (name.isBlank()) {
      throw new IllegalArgumentException("port name '" + name + "': expected not blank");
    }
  }

  /** A port named {@code name} carrying {@code type}. */
  public static <S extends Signal> Port<S> of(String name, Class<S> type) {
    return new Port<>(name, type);
  }

  @Override
  public String toString() {
    return name + ":" + type.getSimpleName();
  }
}

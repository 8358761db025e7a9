package org.armgals.maam.spi;

import static java.util.Objects.requireNonNull;

/**
 * The name and value type of one actuator of a {@link Body}. Two keys are the same actuator when
 * both name and type are equal.
 *
 * @param name lower-case start, then letters, digits, and '.' or '-' between them ({@code
 *     leg.px.target})
 * @param type the class of the commands the actuator takes
 * @param <T> the value type
 */
public record ActuatorKey<T>(String name, Class<T> type) {

  /** Checks the name's syntax. */
  public ActuatorKey {
    Keys.checkName(name);
    requireNonNull(type, "type");
  }

  /** An actuator named {@code name} taking commands of {@code type}. */
  public static <T> ActuatorKey<T> of(String name, Class<T> type) {
    return new ActuatorKey<>(name, type);
  }

  /**
   * {@code value} as this actuator's type.
   *
   * @throws IllegalArgumentException {@code value} is not of the actuator's type
   */
  public T cast(Object value) {
    return Keys.checkValue("actuator", name, type, value);
  }
}

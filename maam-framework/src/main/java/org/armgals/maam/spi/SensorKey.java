package org.armgals.maam.spi;

import static java.util.Objects.requireNonNull;

/**
 * The name and value type of one sensor of a {@link Body}. Two keys are the same sensor when both
 * name and type are equal.
 *
 * @param name lower-case start, then letters, digits, and '.' or '-' between them ({@code
 *     leg.px.contact})
 * @param type the class of the values the sensor reads
 * @param <T> the value type
 */
public record SensorKey<T>(String name, Class<T> type) {

  /** Checks the name's syntax. */
  public SensorKey {
    Keys.checkName(name);
    requireNonNull(type, "type");
  }

  /** A sensor named {@code name} reading values of {@code type}. */
  public static <T> SensorKey<T> of(String name, Class<T> type) {
    return new SensorKey<>(name, type);
  }

  /**
   * {@code value} as this sensor's type.
   *
   * @throws IllegalArgumentException {@code value} is not of the sensor's type
   */
  public T cast(Object value) {
    return Keys.checkValue("sensor", name, type, value);
  }
}

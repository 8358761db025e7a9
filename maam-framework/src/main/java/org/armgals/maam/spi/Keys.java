package org.armgals.maam.spi;

import static java.util.Objects.requireNonNull;

import java.util.regex.Pattern;

/** The checks {@link SensorKey} and {@link ActuatorKey} share. */
final class Keys {

  private static final Pattern NAME = Pattern.compile("[a-z][a-zA-Z0-9]*([.\\-][a-zA-Z0-9]+)*");

  private Keys() {}

  static String checkName(String name) {
    requireNonNull(name, "name");
    if (!NAME.matcher(name).matches()) {
      throw new IllegalArgumentException(
          "name '" + name + "': expected a lower-case start, letters, digits, '.' or '-' inside");
    }
    return name;
  }

  static <T> T checkValue(String what, String name, Class<T> type, Object value) {
    requireNonNull(value, "value");
    if (!type.isInstance(value)) {
      throw new IllegalArgumentException(
          what
              + " '"
              + name
              + "' takes "
              + type.getName()
              + ", got "
              + value.getClass().getName()
              + ": "
              + value);
    }
    return type.cast(value);
  }
}

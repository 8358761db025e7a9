package org.armgals.representation.internal;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.List;
import org.jspecify.annotations.Nullable;

/**
 * The values a {@link org.armgals.representation.State#observe()} may hold: {@code String}, {@code
 * Boolean}, a boxed primitive number, {@code Character}, or a list of those (so that they cross
 * runtimes in a message).
 */
public final class Observables {
  private Observables() {}

  /**
   * {@code value} as an observable value: itself, or an unmodifiable copy of a collection.
   *
   * @throws IllegalArgumentException naming {@code what} and the value when it is not observable
   */
  public static Object check(String what, @Nullable Object value) {
    if (value == null) {
      throw new IllegalArgumentException(what + " is null; expected an observable value");
    }
    if (value instanceof Collection<?> c) {
      List<Object> copy = new ArrayList<>(c.size());
      for (Object o : c) {
        if (o == null || o instanceof Collection<?> || !isScalar(o)) {
          throw notObservable(what, value);
        }
        copy.add(o);
      }
      return Collections.unmodifiableList(copy);
    }
    if (!isScalar(value)) {
      throw notObservable(what, value);
    }
    return value;
  }

  private static boolean isScalar(Object o) {
    return o instanceof String
        || o instanceof Boolean
        || o instanceof Character
        || o instanceof Integer
        || o instanceof Long
        || o instanceof Double
        || o instanceof Float
        || o instanceof Short
        || o instanceof Byte;
  }

  private static IllegalArgumentException notObservable(String what, Object value) {
    return new IllegalArgumentException(
        what
            + " = "
            + value
            + " ("
            + value.getClass().getName()
            + ") is not observable; expected a String, Boolean, Character, boxed number or a List"
            + " of those");
  }

  /**
   * {@code value} converted to {@code type} when it is a number of another boxed type that holds
   * the same value (observations that crossed a runtime may come back as {@code Long} for an {@code
   * Integer}); otherwise {@code value} itself.
   */
  public static Object coerce(Object value, Class<?> type) {
    if (type.isInstance(value) || !(value instanceof Number n)) {
      return value;
    }
    if (type == Double.class) {
      return n.doubleValue();
    }
    if (type == Float.class && (double) n.floatValue() == n.doubleValue()) {
      return n.floatValue();
    }
    boolean integral =
        value instanceof Integer
            || value instanceof Long
            || value instanceof Short
            || value instanceof Byte;
    if (!integral) {
      return value;
    }
    long l = n.longValue();
    if (type == Long.class) {
      return l;
    }
    if (type == Integer.class && l == (int) l) {
      return (int) l;
    }
    if (type == Short.class && l == (short) l) {
      return (short) l;
    }
    if (type == Byte.class && l == (byte) l) {
      return (byte) l;
    }
    return value;
  }
}

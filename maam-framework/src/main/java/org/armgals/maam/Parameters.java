package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * The parameters of a request for a part of a robot's program by name (a schema, a module or a
 * connector of its kind's catalog, {@link RobotKind}): simple values only (strings, booleans, boxed
 * numbers, lists of those), so that a meta in another runtime can send them. The getters check the
 * type and name the part and the parameter in their errors, which the robot acknowledges to its
 * meta as the refusal's reason.
 */
public final class Parameters {
  private final String of;
  private final Map<String, Object> values;

  private Parameters(String of, Map<String, Object> values) {
    this.of = of;
    this.values = values;
  }

  /**
   * {@code values} as the parameters of {@code of} (what they are for, in errors: {@code "schema
   * lift-front"}).
   *
   * @throws IllegalArgumentException a key that is not a string
   */
  public static Parameters of(String of, Map<?, ?> values) {
    requireNonNull(of, "of");
    requireNonNull(values, "values");
    Map<String, Object> copy = new LinkedHashMap<>();
    values.forEach(
        (k, v) -> {
          if (!(k instanceof String name)) {
            throw new IllegalArgumentException(
                "parameter name " + k + " of " + of + ": expected a string");
          }
          copy.put(name, requireNonNull(v, () -> "parameter '" + name + "' of " + of));
        });
    return new Parameters(of, Collections.unmodifiableMap(copy));
  }

  /** No parameters, for {@code of}. */
  public static Parameters none(String of) {
    return of(of, Map.of());
  }

  /**
   * The number {@code name}.
   *
   * @throws IllegalArgumentException absent or not a number
   */
  public double number(String name) {
    return require(name, Number.class, "a number").doubleValue();
  }

  /**
   * The whole number {@code name}.
   *
   * @throws IllegalArgumentException absent, not a number, or not whole
   */
  public long whole(String name) {
    Number n = require(name, Number.class, "a whole number");
    double d = n.doubleValue();
    if (d != Math.rint(d) || Double.isInfinite(d)) {
      throw new IllegalArgumentException(
          "parameter '" + name + "' of " + of + ": expected a whole number, was " + n);
    }
    return n.longValue();
  }

  /**
   * The string {@code name}.
   *
   * @throws IllegalArgumentException absent or not a string
   */
  public String text(String name) {
    return require(name, String.class, "a string");
  }

  /**
   * The boolean {@code name}.
   *
   * @throws IllegalArgumentException absent or not a boolean
   */
  public boolean flag(String name) {
    return require(name, Boolean.class, "a boolean");
  }

  /**
   * The list {@code name}.
   *
   * @throws IllegalArgumentException absent or not a list
   */
  public List<?> list(String name) {
    return require(name, List.class, "a list");
  }

  /** The value {@code name}, if there is one. */
  public Optional<Object> get(String name) {
    return Optional.ofNullable(values.get(requireNonNull(name, "name")));
  }

  /** All of them, in the order given. */
  public Map<String, Object> asMap() {
    return values;
  }

  private <T> T require(String name, Class<T> type, String expected) {
    requireNonNull(name, "name");
    Object v = values.get(name);
    if (v == null) {
      throw new IllegalArgumentException(
          "parameter '"
              + name
              + "' of "
              + of
              + ": expected "
              + expected
              + ", absent from "
              + values);
    }
    if (!type.isInstance(v)) {
      throw new IllegalArgumentException(
          "parameter '" + name + "' of " + of + ": expected " + expected + ", was " + v);
    }
    return type.cast(v);
  }

  @Override
  public String toString() {
    return values.toString();
  }
}

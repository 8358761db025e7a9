package org.armgals.active;

import static java.util.Objects.requireNonNull;

import java.util.Map;
import org.apache.activemq.artemis.api.core.SimpleString;
import org.apache.activemq.artemis.selector.filter.BooleanExpression;
import org.apache.activemq.artemis.selector.filter.FilterException;
import org.apache.activemq.artemis.selector.filter.Filterable;
import org.apache.activemq.artemis.selector.impl.SelectorParser;
import org.jspecify.annotations.Nullable;

/** A {@link Filter} compiled by Artemis's selector parser, the one its broker uses. */
final class SelectorFilter implements Filter {
  private final String expression;
  private final BooleanExpression compiled;

  private SelectorFilter(String expression, BooleanExpression compiled) {
    this.expression = expression;
    this.compiled = compiled;
  }

  static Filter compile(String expression) {
    requireNonNull(expression, "expression");
    if (expression.isBlank()) {
      return Filter.ALL;
    }
    try {
      return new SelectorFilter(expression, SelectorParser.parse(expression));
    } catch (FilterException | RuntimeException e) {
      throw new IllegalArgumentException(
          "not a valid JMS message selector: '" + expression + "': " + e.getMessage(), e);
    }
  }

  @Override
  public String expression() {
    return expression;
  }

  @Override
  public boolean matches(Map<String, ?> properties) {
    checkValues(properties);
    try {
      return compiled.matches(new Properties(properties));
    } catch (FilterException | RuntimeException e) {
      // The broker's FilterImpl treats an evaluation error as "no match"; so do we.
      return false;
    }
  }

  /** Checks that every value is a JMS property type. */
  static void checkValues(Map<String, ?> properties) {
    requireNonNull(properties, "properties");
    properties.forEach(
        (name, value) -> {
          requireNonNull(name, "property name");
          if (!(value instanceof String
              || value instanceof Boolean
              || value instanceof Byte
              || value instanceof Short
              || value instanceof Integer
              || value instanceof Long
              || value instanceof Float
              || value instanceof Double)) {
            throw new IllegalArgumentException(
                "property '"
                    + name
                    + "' is "
                    + (value == null ? "null" : value.getClass().getName() + " " + value)
                    + "; expected a String, Boolean, Byte, Short, Integer, Long, Float or Double");
          }
        });
  }

  /** The properties as Artemis sees a message: strings are {@link SimpleString}s there. */
  private record Properties(Map<String, ?> values) implements Filterable {
    @Override
    public <T> @Nullable T getBodyAs(Class<T> type) {
      return null;
    }

    @Override
    public @Nullable Object getProperty(SimpleString name) {
      return values.get(name.toString());
    }

    @Override
    public @Nullable Object getLocalConnectionId() {
      return null;
    }
  }

  @Override
  public boolean equals(@Nullable Object o) {
    return o instanceof SelectorFilter f && f.expression.equals(expression);
  }

  @Override
  public int hashCode() {
    return expression.hashCode();
  }

  @Override
  public String toString() {
    return "Filter[" + expression + "]";
  }
}

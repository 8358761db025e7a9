package org.armgals.representation.p;

import static java.util.Objects.requireNonNull;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.RecordComponent;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import org.armgals.representation.State;
import org.armgals.representation.internal.Observables;

/**
 * The state of a procedural entity: the values of its fields, by name, in declaration order.
 * Equality is that of the values (the order does not matter). {@link #observe()} is the fields
 * themselves, so that a state event can carry them all or, differentially, only those that changed.
 *
 * <p>A state can be made from a record ({@link #of(Record)}) and turned back into one ({@link
 * #as(Class)}), so that an entity can keep its fields in a record of its own.
 *
 * @param fields names to values; each value is observable (see {@link State#observe()})
 */
public record PState(Map<String, Object> fields) implements State {

  /**
   * Copies {@code fields}, keeping their order.
   *
   * @throws IllegalArgumentException if a value is not observable
   */
  public PState {
    requireNonNull(fields, "fields");
    Map<String, Object> copy = new LinkedHashMap<>();
    fields.forEach(
        (name, value) -> {
          requireNonNull(name, "field name");
          requireNonNull(value, () -> "value of field '" + name + "'");
          copy.put(name, Observables.check("field '" + name + "'", value));
        });
    fields = Collections.unmodifiableMap(copy);
  }

  /**
   * The state holding the components of {@code record}, by component name.
   *
   * @throws IllegalArgumentException if a component's value is not observable, or the record's
   *     class cannot be read reflectively
   */
  public static PState of(Record record) {
    requireNonNull(record, "record");
    Map<String, Object> fields = new LinkedHashMap<>();
    for (RecordComponent c : record.getClass().getRecordComponents()) {
      try {
        c.getAccessor().setAccessible(true);
        Object value = c.getAccessor().invoke(record);
        fields.put(c.getName(), requireNonNull(value, () -> "component '" + c.getName() + "'"));
      } catch (IllegalAccessException | InvocationTargetException | RuntimeException e) {
        throw new IllegalArgumentException(
            "cannot read component '" + c.getName() + "' of " + record.getClass().getName(), e);
      }
    }
    return new PState(fields);
  }

  /** The value of field {@code name}. */
  public Object get(String name) {
    Object value = fields.get(requireNonNull(name, "name"));
    if (value == null) {
      throw new IllegalArgumentException("no field '" + name + "'; fields: " + fields.keySet());
    }
    return value;
  }

  /**
   * This state with field {@code name} set to {@code value}.
   *
   * @throws IllegalArgumentException if there is no such field or the value is not observable
   */
  public PState with(String name, Object value) {
    get(name);
    Map<String, Object> next = new LinkedHashMap<>(fields);
    next.put(name, requireNonNull(value, "value"));
    return new PState(next);
  }

  /**
   * This state as a record of {@code type}, whose components are named as the fields.
   *
   * @throws IllegalArgumentException if the components and the fields do not match, or the record
   *     cannot be built reflectively
   */
  public <R extends Record> R as(Class<R> type) {
    requireNonNull(type, "type");
    RecordComponent[] components = type.getRecordComponents();
    if (components == null) {
      throw new IllegalArgumentException(type.getName() + " is not a record; expected a record");
    }
    Class<?>[] types = new Class<?>[components.length];
    Object[] args = new Object[components.length];
    for (int i = 0; i < components.length; i++) {
      types[i] = components[i].getType();
      args[i] = Observables.coerce(get(components[i].getName()), box(types[i]));
    }
    if (components.length != fields.size()) {
      throw new IllegalArgumentException(
          "fields " + fields.keySet() + " do not match the components of " + type.getName());
    }
    try {
      Constructor<R> canonical = type.getDeclaredConstructor(types);
      canonical.setAccessible(true);
      return canonical.newInstance(args);
    } catch (ReflectiveOperationException | RuntimeException e) {
      throw new IllegalArgumentException("cannot build a " + type.getName() + " from " + this, e);
    }
  }

  static Class<?> box(Class<?> type) {
    if (!type.isPrimitive()) {
      return type;
    }
    return switch (type.getName()) {
      case "int" -> Integer.class;
      case "long" -> Long.class;
      case "double" -> Double.class;
      case "float" -> Float.class;
      case "boolean" -> Boolean.class;
      case "char" -> Character.class;
      case "short" -> Short.class;
      case "byte" -> Byte.class;
      default -> throw new IllegalArgumentException("field type " + type + " is not observable");
    };
  }

  @Override
  public Map<String, Object> observe() {
    return fields;
  }

  @Override
  public String toString() {
    return "PState" + fields;
  }
}

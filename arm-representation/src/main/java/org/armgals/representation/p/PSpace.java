package org.armgals.representation.p;

import static java.util.Objects.requireNonNull;

import java.lang.reflect.RecordComponent;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.armgals.representation.Behaviors;
import org.armgals.representation.StateSpace;

/**
 * The state space of a procedural entity: the product of its fields' types. It maps observations
 * back to states, filling the fields a differential state event leaves out from the state the
 * observer had.
 *
 * <p>Immutable and thread-safe.
 */
public interface PSpace extends StateSpace<PState> {

  /**
   * The space of the fields of {@code initial}, each typed by the class of its value ({@code List}
   * for a list), starting in {@code initial}.
   */
  static PSpace of(PState initial) {
    requireNonNull(initial, "initial");
    Map<String, Class<?>> types = new LinkedHashMap<>();
    initial
        .fields()
        .forEach(
            (name, value) ->
                types.put(name, value instanceof List ? List.class : value.getClass()));
    return new PSpaceImpl(types, initial);
  }

  /**
   * The space of the components of {@code initial}'s record type, starting in {@code initial}. A
   * primitive component is typed by its box, a {@code List} component by {@code List}.
   */
  static PSpace ofRecord(Record initial) {
    PState state = PState.of(initial);
    Map<String, Class<?>> types = new LinkedHashMap<>();
    for (RecordComponent c : initial.getClass().getRecordComponents()) {
      Class<?> t = PState.box(c.getType());
      types.put(c.getName(), List.class.isAssignableFrom(t) ? List.class : t);
    }
    return new PSpaceImpl(types, state);
  }

  /** The fields, by name in declaration order, with their types. */
  Map<String, Class<?>> fields();

  /** A method dictionary holding {@code methods}, in that order. */
  Behaviors<PState> methods(PMethod... methods);
}

package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.HashMap;
import java.util.Map;
import java.util.function.BiFunction;
import org.armgals.representation.Behavior;
import org.armgals.representation.BehaviorNotApplicableException;
import org.armgals.representation.Step;
import org.jspecify.annotations.Nullable;

/** A behavior of the field representation: a pure function of the fields and an input. */
final class FieldBehavior implements Behavior<FieldState> {
  private final String name;
  private final BiFunction<Map<String, Object>, @Nullable Object, Map<String, Object>> next;

  FieldBehavior(
      String name, BiFunction<Map<String, Object>, @Nullable Object, Map<String, Object>> next) {
    this.name = requireNonNull(name, "name");
    this.next = requireNonNull(next, "next");
  }

  /** A behavior that sets field {@code field} to its input. */
  static FieldBehavior setting(String name, String field) {
    return new FieldBehavior(
        name,
        (fields, input) -> {
          Map<String, Object> m = new HashMap<>(fields);
          m.put(field, requireNonNull(input, "input"));
          return m;
        });
  }

  @Override
  public String name() {
    return name;
  }

  @Override
  public boolean isApplicable(FieldState state, @Nullable Object input) {
    return true;
  }

  @Override
  public Step<FieldState> apply(FieldState state, @Nullable Object input) {
    Map<String, Object> after;
    try {
      after = next.apply(state.fields(), input);
    } catch (RuntimeException e) {
      throw new BehaviorNotApplicableException(name, state);
    }
    return new Step<>(state, new FieldState(after), name, null);
  }

  @Override
  public String toString() {
    return name;
  }
}

package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import org.armgals.representation.Activation;
import org.armgals.representation.Behaviors;
import org.armgals.representation.StateSpace;
import org.jspecify.annotations.Nullable;

/**
 * The space of {@link FieldState}s: every map of simple values. A partial observation keeps the
 * current values of the names it leaves out.
 */
final class FieldSpace implements StateSpace<FieldState> {

  static final FieldSpace INSTANCE = new FieldSpace();

  private FieldSpace() {}

  @Override
  public FieldState initialState() {
    return FieldState.EMPTY;
  }

  @Override
  public boolean contains(FieldState state) {
    requireNonNull(state, "state");
    return true;
  }

  @Override
  public Set<FieldState> mapToState(Map<String, ?> observation, @Nullable FieldState current) {
    Map<String, Object> fields = new HashMap<>(current == null ? Map.of() : current.fields());
    fields.putAll(observation);
    return Set.of(new FieldState(fields));
  }

  @Override
  public Activation<FieldState> activate(FieldState initial, Behaviors<FieldState> behaviors) {
    return new FieldActivation(initial, behaviors);
  }
}

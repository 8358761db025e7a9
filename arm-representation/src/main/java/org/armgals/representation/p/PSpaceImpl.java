package org.armgals.representation.p;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.armgals.representation.Activation;
import org.armgals.representation.Behaviors;
import org.armgals.representation.internal.Observables;
import org.armgals.representation.internal.OrderedBehaviors;
import org.jspecify.annotations.Nullable;

/** A product of field types; see {@link PSpace}. */
final class PSpaceImpl implements PSpace {
  /** Any behavior of procedural states may join a method dictionary. */
  static final OrderedBehaviors.Admission<PState> ANY = (candidate, others) -> {};

  private final Map<String, Class<?>> fields;
  private final PState initial;

  PSpaceImpl(Map<String, Class<?>> fields, PState initial) {
    this.fields = Collections.unmodifiableMap(new LinkedHashMap<>(fields));
    if (!contains(initial)) {
      throw new IllegalArgumentException(
          "initial state " + initial + " does not fit the fields " + this.fields);
    }
    this.initial = initial;
  }

  @Override
  public Map<String, Class<?>> fields() {
    return fields;
  }

  @Override
  public Behaviors<PState> methods(PMethod... methods) {
    Behaviors<PState> result = OrderedBehaviors.empty(ANY);
    for (PMethod m : methods) {
      result = result.with(m);
    }
    return result;
  }

  @Override
  public PState initialState() {
    return initial;
  }

  @Override
  public boolean contains(PState state) {
    requireNonNull(state, "state");
    if (!state.fields().keySet().equals(fields.keySet())) {
      return false;
    }
    for (Map.Entry<String, Class<?>> f : fields.entrySet()) {
      if (!f.getValue().isInstance(state.fields().get(f.getKey()))) {
        return false;
      }
    }
    return true;
  }

  @Override
  public Set<PState> mapToState(Map<String, ?> observation, @Nullable PState current) {
    requireNonNull(observation, "observation");
    Map<String, Object> values = new LinkedHashMap<>();
    for (Map.Entry<String, ?> e : observation.entrySet()) {
      String name = requireNonNull(e.getKey(), "observed name");
      Class<?> type = fields.get(name);
      if (type == null) {
        throw new IllegalArgumentException(
            "observation names '" + name + "', which is not a field; fields: " + fields.keySet());
      }
      Object value = e.getValue();
      if (value == null) {
        throw new IllegalArgumentException("observation of field '" + name + "' is null");
      }
      value = Observables.coerce(Observables.check("field '" + name + "'", value), type);
      if (!type.isInstance(value)) {
        throw new IllegalArgumentException(
            "observation of field '"
                + name
                + "' = "
                + value
                + " ("
                + value.getClass().getName()
                + "); expected a "
                + type.getName());
      }
      values.put(name, value);
    }
    List<String> missing = new ArrayList<>();
    for (String name : fields.keySet()) {
      if (!values.containsKey(name)) {
        missing.add(name);
      }
    }
    if (!missing.isEmpty()) {
      if (current == null) {
        throw new IllegalArgumentException(
            "observation lacks fields "
                + missing
                + " and there is no current state to take them from; expected every field or a"
                + " current state");
      }
      if (!contains(current)) {
        throw new IllegalArgumentException("current state " + current + " is not in the space");
      }
    }
    Map<String, Object> state = new LinkedHashMap<>();
    for (String name : fields.keySet()) {
      Object value = values.get(name);
      state.put(name, value != null ? value : requireNonNull(current).fields().get(name));
    }
    return Set.of(new PState(state));
  }

  @Override
  public Activation<PState> activate(PState initial, Behaviors<PState> behaviors) {
    return new PActivation(this, initial, behaviors);
  }

  @Override
  public String toString() {
    return "PSpace" + fields;
  }
}

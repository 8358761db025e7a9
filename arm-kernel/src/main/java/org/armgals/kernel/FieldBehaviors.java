package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.armgals.representation.Behavior;
import org.armgals.representation.Behaviors;
import org.armgals.representation.NoSuchBehaviorException;
import org.armgals.representation.State;

/** An immutable method dictionary, in insertion order, for any state type. */
final class FieldBehaviors<S extends State> implements Behaviors<S> {
  private final Map<String, Behavior<S>> byName;

  private FieldBehaviors(Map<String, Behavior<S>> byName) {
    this.byName = Collections.unmodifiableMap(byName);
  }

  @SafeVarargs
  static <S extends State> FieldBehaviors<S> of(Behavior<S>... behaviors) {
    Map<String, Behavior<S>> m = new LinkedHashMap<>();
    for (Behavior<S> b : behaviors) {
      m.put(b.name(), b);
    }
    return new FieldBehaviors<>(m);
  }

  @Override
  public Optional<Behavior<S>> lookup(String name) {
    return Optional.ofNullable(byName.get(requireNonNull(name, "name")));
  }

  @Override
  public Behaviors<S> with(Behavior<S> behavior) {
    Map<String, Behavior<S>> m = new LinkedHashMap<>(byName);
    m.put(behavior.name(), behavior);
    return new FieldBehaviors<>(m);
  }

  @Override
  public Behaviors<S> without(String name) {
    if (!byName.containsKey(name)) {
      throw new NoSuchBehaviorException(name, byName.keySet());
    }
    Map<String, Behavior<S>> m = new LinkedHashMap<>(byName);
    m.remove(name);
    return new FieldBehaviors<>(m);
  }

  @Override
  public Set<String> names() {
    return byName.keySet();
  }

  @Override
  public Collection<Behavior<S>> all() {
    return byName.values();
  }
}

package org.armgals.representation.internal;

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

/**
 * An immutable set of behaviors in insertion order, with an admission rule that a family uses to
 * refuse behaviors it cannot run (a transition to a state outside its space, a second transition on
 * the same label from a state).
 *
 * @param <S> the state type of the family
 */
public final class OrderedBehaviors<S extends State> implements Behaviors<S> {

  /** A family's rule for what a behavior set may hold. */
  @FunctionalInterface
  public interface Admission<S extends State> {
    /**
     * Checks that {@code candidate} may join {@code others} (which no longer hold a behavior of the
     * candidate's name).
     *
     * @throws IllegalArgumentException naming the candidate and what was expected
     */
    void check(Behavior<S> candidate, Collection<Behavior<S>> others);
  }

  private final Map<String, Behavior<S>> byName;
  private final Admission<S> admission;

  private OrderedBehaviors(Map<String, Behavior<S>> byName, Admission<S> admission) {
    this.byName = Collections.unmodifiableMap(byName);
    this.admission = admission;
  }

  /** The empty set under {@code admission}. */
  public static <S extends State> OrderedBehaviors<S> empty(Admission<S> admission) {
    return new OrderedBehaviors<>(new LinkedHashMap<>(), requireNonNull(admission, "admission"));
  }

  /**
   * {@code behaviors} as a set under {@code admission}: itself when it already is one, otherwise
   * its behaviors added one by one, in order, so that each is checked.
   *
   * @throws IllegalArgumentException naming the first behavior {@code admission} refuses
   */
  public static <S extends State> OrderedBehaviors<S> admit(
      Behaviors<S> behaviors, Admission<S> admission) {
    requireNonNull(behaviors, "behaviors");
    if (behaviors instanceof OrderedBehaviors<S> ordered && ordered.admission == admission) {
      return ordered;
    }
    OrderedBehaviors<S> result = empty(admission);
    for (Behavior<S> b : behaviors.all()) {
      result = result.with(b);
    }
    return result;
  }

  @Override
  public Optional<Behavior<S>> lookup(String name) {
    return Optional.ofNullable(byName.get(requireNonNull(name, "name")));
  }

  @Override
  public OrderedBehaviors<S> with(Behavior<S> behavior) {
    requireNonNull(behavior, "behavior");
    String name = requireNonNull(behavior.name(), "behavior.name()");
    Map<String, Behavior<S>> others = new LinkedHashMap<>(byName);
    others.remove(name);
    admission.check(behavior, Collections.unmodifiableCollection(others.values()));
    // A replacement keeps the replaced behavior's place, so that priorities derived from the
    // order stay put.
    Map<String, Behavior<S>> next = new LinkedHashMap<>(byName);
    next.put(name, behavior);
    return new OrderedBehaviors<>(next, admission);
  }

  @Override
  public OrderedBehaviors<S> without(String name) {
    requireNonNull(name, "name");
    if (!byName.containsKey(name)) {
      throw new NoSuchBehaviorException(name, byName.keySet());
    }
    Map<String, Behavior<S>> next = new LinkedHashMap<>(byName);
    next.remove(name);
    return new OrderedBehaviors<>(next, admission);
  }

  @Override
  public Set<String> names() {
    return byName.keySet();
  }

  @Override
  public Collection<Behavior<S>> all() {
    return byName.values();
  }

  @Override
  public String toString() {
    return "Behaviors" + byName.keySet();
  }
}

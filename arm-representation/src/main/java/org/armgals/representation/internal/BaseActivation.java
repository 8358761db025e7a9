package org.armgals.representation.internal;

import static java.util.Objects.requireNonNull;

import org.armgals.representation.Activation;
import org.armgals.representation.Behavior;
import org.armgals.representation.BehaviorNotApplicableException;
import org.armgals.representation.Behaviors;
import org.armgals.representation.NoSuchBehaviorException;
import org.armgals.representation.State;
import org.armgals.representation.StateSpace;
import org.armgals.representation.Step;
import org.jspecify.annotations.Nullable;

/**
 * The part of an activation every family shares: the current state, the behaviors, applying a
 * behavior by name, harmonizing and resetting. A family adds {@link Activation#dispatch}.
 *
 * <p>Not thread-safe, as {@link Activation} says.
 *
 * @param <S> the state type of the family
 */
public abstract class BaseActivation<S extends State> implements Activation<S> {
  private final StateSpace<S> space;
  private S state;
  private final OrderedBehaviors.Admission<S> admission;
  private Behaviors<S> behaviors;

  /**
   * An activation in {@code initial}, with {@code behaviors}.
   *
   * @throws IllegalArgumentException if {@code initial} is not in {@code space}, or if {@code
   *     behaviors} holds a behavior the family does not accept
   */
  protected BaseActivation(
      StateSpace<S> space,
      S initial,
      Behaviors<S> behaviors,
      OrderedBehaviors.Admission<S> admission) {
    this.space = requireNonNull(space, "space");
    requireNonNull(initial, "initial");
    if (!space.contains(initial)) {
      throw new IllegalArgumentException(
          "initial state " + initial + " is not in the space; expected one of its states");
    }
    this.state = initial;
    this.admission = requireNonNull(admission, "admission");
    this.behaviors = OrderedBehaviors.admit(behaviors, admission);
  }

  @Override
  public final StateSpace<S> space() {
    return space;
  }

  @Override
  public final S state() {
    return state;
  }

  @Override
  public final Behaviors<S> behaviors() {
    return behaviors;
  }

  @Override
  public final Step<S> apply(String behavior, @Nullable Object input) {
    requireNonNull(behavior, "behavior");
    Behavior<S> b = behavior(behavior);
    if (!b.isApplicable(state, input)) {
      throw new BehaviorNotApplicableException(behavior, state);
    }
    Step<S> step = b.apply(state, input);
    moveTo(step);
    return step;
  }

  /**
   * The behavior {@code name} names, for {@link #apply}: by default the one of that name among the
   * behaviors. A family whose steps may take several behaviors at once (a statechart's microstep)
   * answers a behavior for such a step's name too.
   *
   * @throws NoSuchBehaviorException if there is none
   */
  protected Behavior<S> behavior(String name) {
    return behaviors
        .lookup(name)
        .orElseThrow(() -> new NoSuchBehaviorException(name, behaviors.names()));
  }

  /**
   * Moves to the state {@code step} leads to.
   *
   * @throws IllegalStateException if that state is outside the space (a behavior broke its family's
   *     rules); the current state is then unchanged
   */
  protected final void moveTo(Step<S> step) {
    if (!space.contains(step.after())) {
      throw new IllegalStateException(
          "behavior '"
              + step.behavior()
              + "' led to "
              + step.after()
              + ", which is not in the space; the state stays "
              + state);
    }
    state = step.after();
  }

  @Override
  public final void harmonize(Behaviors<S> behaviors) {
    this.behaviors = OrderedBehaviors.admit(behaviors, admission);
  }

  @Override
  public final void reset(S state) {
    requireNonNull(state, "state");
    if (!space.contains(state)) {
      throw new IllegalArgumentException(
          "state " + state + " is not in the space; expected one of its states");
    }
    this.state = state;
  }

  @Override
  public String toString() {
    return getClass().getSimpleName() + "[" + state + ", " + behaviors + "]";
  }
}

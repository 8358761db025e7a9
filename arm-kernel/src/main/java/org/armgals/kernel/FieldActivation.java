package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.List;
import org.armgals.representation.Activation;
import org.armgals.representation.Behavior;
import org.armgals.representation.BehaviorNotApplicableException;
import org.armgals.representation.Behaviors;
import org.armgals.representation.NoSuchBehaviorException;
import org.armgals.representation.StateSpace;
import org.armgals.representation.Step;
import org.jspecify.annotations.Nullable;

/** An activation of the field representation: a current state and a method dictionary. */
final class FieldActivation implements Activation<FieldState> {
  private FieldState state;
  private Behaviors<FieldState> behaviors;

  FieldActivation(FieldState initial, Behaviors<FieldState> behaviors) {
    this.state = requireNonNull(initial, "initial");
    this.behaviors = requireNonNull(behaviors, "behaviors");
  }

  @Override
  public StateSpace<FieldState> space() {
    return FieldSpace.INSTANCE;
  }

  @Override
  public FieldState state() {
    return state;
  }

  @Override
  public Behaviors<FieldState> behaviors() {
    return behaviors;
  }

  @Override
  public Step<FieldState> apply(String behavior, @Nullable Object input) {
    Behavior<FieldState> b =
        behaviors
            .lookup(behavior)
            .orElseThrow(() -> new NoSuchBehaviorException(behavior, behaviors.names()));
    if (!b.isApplicable(state, input)) {
      throw new BehaviorNotApplicableException(behavior, state);
    }
    Step<FieldState> step = b.apply(state, input);
    state = step.after();
    return step;
  }

  @Override
  public List<Step<FieldState>> dispatch(String trigger, @Nullable Object input) {
    var b = behaviors.lookup(trigger);
    if (b.isEmpty() || !b.get().isApplicable(state, input)) {
      return List.of();
    }
    return List.of(apply(trigger, input));
  }

  @Override
  public void harmonize(Behaviors<FieldState> next) {
    this.behaviors = requireNonNull(next, "behaviors");
  }

  @Override
  public void reset(FieldState next) {
    this.state = requireNonNull(next, "state");
  }
}

package org.armgals.representation.p;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.Optional;
import org.armgals.representation.Behavior;
import org.armgals.representation.Behaviors;
import org.armgals.representation.Step;
import org.armgals.representation.internal.BaseActivation;
import org.jspecify.annotations.Nullable;

/** A procedural entity run: a trigger calls the method of that name. */
final class PActivation extends BaseActivation<PState> {

  PActivation(PSpaceImpl space, PState initial, Behaviors<PState> behaviors) {
    super(space, initial, behaviors, PSpaceImpl.ANY);
  }

  /**
   * Applies the method named {@code trigger}; nothing (an empty list) when there is no such method
   * or its guard is false.
   */
  @Override
  public List<Step<PState>> dispatch(String trigger, @Nullable Object input) {
    Optional<Behavior<PState>> method = behaviors().lookup(requireNonNull(trigger, "trigger"));
    if (method.isEmpty() || !method.get().isApplicable(state(), input)) {
      return List.of();
    }
    return List.of(apply(trigger, input));
  }
}

package org.armgals.representation.p;

import static java.util.Objects.requireNonNull;

import java.util.function.BiFunction;
import java.util.function.BiPredicate;
import org.armgals.representation.Behavior;
import org.armgals.representation.BehaviorNotApplicableException;
import org.armgals.representation.Step;
import org.jspecify.annotations.Nullable;

/**
 * A method of a procedural entity: a named pure function from a state and an input to a new state
 * and a result, applicable when its guard holds.
 *
 * <p>The guard and the body must not mutate anything or read anything but their arguments: a
 * behavioral meta replays the method on its model of the entity (paper §3.3, action events).
 *
 * @param name the method's name, what an action event carries
 * @param guard when the method is applicable
 * @param body the new state and the result
 */
public record PMethod(
    String name,
    BiPredicate<PState, @Nullable Object> guard,
    BiFunction<PState, @Nullable Object, Outcome> body)
    implements Behavior<PState> {

  /** What a method body answers: the new state and the method's result. */
  public record Outcome(PState state, @Nullable Object result) {
    /** Checks that the state is there. */
    public Outcome {
      requireNonNull(state, "state");
    }
  }

  /** Checks the components. */
  public PMethod {
    requireNonNull(name, "name");
    if (name.isBlank()) {
      throw new IllegalArgumentException("method name '" + name + "' is blank; expected a name");
    }
    requireNonNull(guard, "guard");
    requireNonNull(body, "body");
  }

  /** A method that updates the state and has no result, always applicable. */
  public static PMethod of(String name, BiFunction<PState, @Nullable Object, PState> update) {
    requireNonNull(update, "update");
    return new PMethod(name, (s, in) -> true, (s, in) -> new Outcome(update.apply(s, in), null));
  }

  /** A method with a result, always applicable. */
  public static PMethod returning(String name, BiFunction<PState, @Nullable Object, Outcome> body) {
    return new PMethod(name, (s, in) -> true, body);
  }

  /** This method, applicable only when {@code guard} holds. */
  public PMethod when(BiPredicate<PState, @Nullable Object> guard) {
    return new PMethod(name, guard, body);
  }

  @Override
  public boolean isApplicable(PState state, @Nullable Object input) {
    return guard.test(requireNonNull(state, "state"), input);
  }

  @Override
  public Step<PState> apply(PState state, @Nullable Object input) {
    if (!isApplicable(state, input)) {
      throw new BehaviorNotApplicableException(name, state);
    }
    Outcome outcome =
        requireNonNull(body.apply(state, input), () -> "method '" + name + "' answered no Outcome");
    return new Step<>(state, outcome.state(), name, outcome.result());
  }

  @Override
  public String toString() {
    return "PMethod[" + name + "]";
  }
}

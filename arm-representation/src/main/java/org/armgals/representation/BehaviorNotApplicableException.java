package org.armgals.representation;

import static java.util.Objects.requireNonNull;

/** Thrown when a behavior is applied in a state where it is not applicable. */
public final class BehaviorNotApplicableException extends RepresentationException {
  private static final long serialVersionUID = 1L;
  private final String behavior;

  /**
   * The exception, its message naming the behavior and the state.
   *
   * @param behavior the behavior's name
   * @param state the state it was applied in, for the message
   */
  public BehaviorNotApplicableException(String behavior, State state) {
    super(
        "behavior '"
            + requireNonNull(behavior, "behavior")
            + "' is not applicable in state "
            + requireNonNull(state, "state"));
    this.behavior = behavior;
  }

  /** The behavior's name. */
  public String behavior() {
    return behavior;
  }
}

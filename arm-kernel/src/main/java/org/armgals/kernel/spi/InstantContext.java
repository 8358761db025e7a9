package org.armgals.kernel.spi;

import java.util.List;
import org.armgals.kernel.Entity;
import org.armgals.kernel.Stimulus;
import org.armgals.representation.State;
import org.jspecify.annotations.Nullable;

/**
 * What a {@link ReactiveProgram} sees of one instant of its entity and may do in it. Valid only
 * during the call to {@link ReactiveProgram#react} it was given to, on that thread.
 */
public interface InstantContext {

  /** The instant of the entity's clock, from 1. */
  long instant();

  /** The entity running the program. */
  Entity self();

  /**
   * The stimuli the entity took at this release, in the instant's order (by sender, then send
   * order). A reactive entity with a program does not dispatch them to its activation: the program
   * reads them.
   */
  List<Stimulus> stimuli();

  /** The entity's reified state now. */
  State state();

  /**
   * Applies the behavior named {@code behavior} of the entity's activation with {@code input} (the
   * reified side of what the program did), and notifies the behavioral meta of the step as the
   * notification policy says: an action event, a state event if what is observed changed, the
   * thresholds crossed.
   *
   * @return the behavior's result
   * @throws org.armgals.representation.NoSuchBehaviorException no behavior of that name
   * @throws org.armgals.representation.BehaviorNotApplicableException not applicable now
   */
  @Nullable Object apply(String behavior, @Nullable Object input);
}

package org.armgals.kernel.spi;

import org.armgals.kernel.Adaptation;
import org.armgals.representation.Behaviors;

/**
 * The base-level program of a reactive entity (paper §5.3-5.4, figure 8): what the entity does at
 * each release of its clock, besides taking the events waiting there. A robot is such a program: it
 * reads its sensors, runs its behavior modules and tells its reified state to the kernel with
 * {@link InstantContext#apply}, which notifies the behavioral meta as the entity's notification
 * policy says.
 *
 * <p>Threading: called on the entity's own object, once per release, never concurrently with
 * itself; {@link #adapt} is called on the same object, between two instants (at the entity's
 * adaptation point), never during {@link #react}.
 */
public interface ReactiveProgram {

  /**
   * One instant of the entity.
   *
   * @throws Exception a failure of this instant: notified to the behavioral meta as a {@link
   *     org.armgals.kernel.FailureEvent} and counted by the runtime; the entity goes on at the next
   *     release
   */
  void react(InstantContext instant) throws Exception;

  /**
   * Applies the program's side of {@code adaptation}, before the entity's activation applies its
   * reified side (for {@link Adaptation.ApplyBehavior}, the behavior of that name): a robot swaps a
   * module, adds a schema, reschedules. The default does nothing: the reified behavior is all.
   *
   * @throws IllegalArgumentException the program refuses it (an unknown name, a change that would
   *     break it): nothing is applied and the meta is acknowledged the refusal with this message
   */
  default void adapt(Adaptation adaptation) {}

  /**
   * The entity's structural meta replaced its behaviors (flow 5 of the paper's §3.1: a behavior
   * taught to or removed from its kind while it runs): the program takes what it must from them (a
   * robot drops a schema its kind no longer has, at its next adaptation point). Called on the
   * entity's object, when it processes the harmonization, never during {@link #react}. Does nothing
   * by default.
   */
  default void harmonized(Behaviors<?> behaviors) {}
}

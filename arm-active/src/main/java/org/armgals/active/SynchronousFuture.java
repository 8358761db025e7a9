package org.armgals.active;

/**
 * The future a synchronous (reactive) object gets for a synchronized request without a value (paper
 * §5.2-5.3): it implements <em>active wait</em>. The reply arrives as a {@link FutureEvent} in the
 * object's buffer and is taken, like any other event, at a release of its clock; from then on
 * {@link #isDone()} answers {@code true}. Until then {@link #touch()} does not wait: it throws
 * {@link FutureNotAvailableException}, and the cycle goes on. A reactive behavior tests {@code
 * isDone()} at each instant.
 *
 * <p>Threading: meant to be used by its owning object only.
 */
public interface SynchronousFuture extends Future {}

package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * The future a synchronous (reactive) object gets for a synchronized request with a value: {@link
 * #getValue()} answers the value once its {@link FutureEvent} has been taken at a release, and
 * otherwise throws {@link FutureNotAvailableException} without waiting. See {@link
 * SynchronousFuture}.
 *
 * @param <T> the value type
 */
public interface SynchronousFutureValue<T extends @Nullable Object>
    extends FutureValue<T>, SynchronousFuture {}

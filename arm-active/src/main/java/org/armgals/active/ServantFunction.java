package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * A synchronized request: code run by an active object on its servant, whose result completes a
 * {@link FutureValue}.
 *
 * @param <S> the servant type
 * @param <R> the result type
 */
@FunctionalInterface
public interface ServantFunction<S, R extends @Nullable Object> {
  /** Runs on the servant, on the object's own thread. */
  R apply(S servant) throws Exception;
}

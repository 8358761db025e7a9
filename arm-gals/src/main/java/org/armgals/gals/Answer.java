package org.armgals.gals;

import org.armgals.active.Request;
import org.jspecify.annotations.Nullable;

/**
 * How a reactive entity answers the data {@link Request}s sent to it with {@link CycleContext#ask}
 * (from its runtime or another one): run on the entity's thread when it takes the request, at its
 * island's release, before its reactions. Set with {@link ReactiveEntity#answerWith}.
 *
 * @param <S> the type of the entity's state
 */
@FunctionalInterface
public interface Answer<S> {

  /**
   * The answer to {@code request}, of the type the request names; an encodable value when the asker
   * is in another runtime.
   *
   * @throws Exception any failure: the asker's awaited value becomes {@link
   *     AwaitedValue.Status#FAILED} with it
   */
  @Nullable Object answer(S state, Request<?> request) throws Exception;
}

package org.armgals.gals;

import java.time.Duration;
import java.util.List;
import org.armgals.active.Address;
import org.armgals.active.Request;
import org.armgals.active.ServantFunction;
import org.jspecify.annotations.Nullable;

/**
 * What a {@link Reaction} sees of its cycle and may do in it. Valid only during the call to {@link
 * Reaction#react} it was given to, on that thread.
 *
 * @param <S> the type of the entity's state
 */
public interface CycleContext<S> {

  /** The island's instant, 1 for the first cycle. */
  long instant();

  /** The entity's state; only its own reactions and adaptations touch it. */
  S state();

  /**
   * The payloads the entity took at this release, ordered by sender (address, then send order),
   * those sent from outside any entity last in arrival order. The same list for every reaction of
   * the cycle.
   */
  List<Object> inputs();

  /**
   * Sends {@code payload} to {@code target}, which sees it at its next release: instant {@code k +
   * 1} in this island, the next release of the target's island otherwise. Never blocks; when the
   * target's buffer is full its oldest event is dropped.
   */
  void emit(ReactiveEntity<?> target, Object payload);

  /**
   * Sends {@code payload} to the reactive entity at {@code target}, in this runtime or in another
   * one on the same broker (an address from {@link ReactiveEntity#address()}, passed along or found
   * with {@code JmsTransport.lookup}); it is taken at the next release of the target's island after
   * it arrives, in send order from this entity. To another runtime the payload is encoded on this
   * thread, so {@link Emission} and the payload's type must be on the transport's allow-list. Never
   * blocks.
   *
   * @throws IllegalArgumentException the target is in another runtime and the payload's type is not
   *     on the allow-list (the message names it), or this runtime has no transport
   * @throws org.armgals.active.ObjectStoppedException the target is in this runtime and stopped
   */
  void emit(Address target, Object payload);

  /**
   * Asks {@code target} for a value: {@code query} runs on the target's state when the target takes
   * the request (its next release), and the answer comes back as an event at a later release of
   * this entity. The awaited value belongs to the reaction running now: it times out after {@code
   * timeout} (rounded up to whole periods of this island, at least one) and is cancelled if that
   * reaction is removed.
   *
   * @throws IllegalArgumentException {@code timeout} is not positive
   */
  <T, R extends @Nullable Object> AwaitedValue<R> call(
      ReactiveEntity<T> target, ServantFunction<? super T, R> query, Duration timeout);

  /**
   * Asks the reactive entity at {@code target}, in this runtime or another one on the same broker,
   * with a data {@code request} (its destination is {@code target}): the target's {@link
   * ReactiveEntity#answerWith answer} runs when it takes the request (the first release of its
   * island after the request arrives), and the answer completes the awaited value, whose status
   * changes at the beginning of a later cycle of this entity. The value belongs to the reaction
   * running now, times out and is cancelled as with {@link #call}. To another runtime the request
   * is encoded on this thread: its type and the answer's must be on the transports' allow-list.
   *
   * @throws IllegalArgumentException {@code timeout} is not positive, the request is addressed to
   *     another destination, or its type is not on the allow-list
   */
  <R extends @Nullable Object> AwaitedValue<R> ask(
      Address target, Request<R> request, Duration timeout);

  /** Adds a line to the island's per-cycle trace (when tracing is on; otherwise does nothing). */
  void trace(String line);

  /**
   * Whether the island keeps its trace: a reaction checks it before building an expensive line for
   * {@link #trace}.
   */
  boolean tracing();
}

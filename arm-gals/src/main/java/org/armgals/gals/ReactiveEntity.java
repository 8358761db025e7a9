package org.armgals.gals;

import java.util.List;
import java.util.function.Consumer;
import org.armgals.active.Address;
import org.armgals.active.FutureValue;
import org.armgals.active.ServantFunction;
import org.jspecify.annotations.Nullable;

/**
 * A reactive entity (paper §5.3): a state and named {@link Reaction reactions}, run as a
 * synchronous active object released by its {@link Island}. Made by {@link Island#spawn}.
 *
 * <p>PendingAdaptation: {@link #addReaction}, {@link #removeReaction} and {@link #adapt} are
 * requests. They return at once and are applied by the island between two instants, at its {@link
 * org.armgals.kernel.AdaptationPoint}, in the order they were made, never while the entity reacts.
 *
 * <p>Threading: every method may be called from any thread.
 *
 * @param <S> the type of its state
 */
public sealed interface ReactiveEntity<S> permits EntityImpl {

  /** Its name, unique in its island. */
  String name();

  /** The address of its active object. */
  Address address();

  /** The island that releases it. */
  Island island();

  /**
   * Sends {@code payload} from outside any reaction (another thread, an asynchronous object); it is
   * taken at the entity's next release. Inside a reaction use {@link CycleContext#emit}.
   */
  void send(Object payload);

  /**
   * Asks a value of its state from outside any reaction: {@code query} runs at the entity's next
   * release and the future completes then (it waits by necessity, as futures of asynchronous
   * objects do). Inside a reaction use {@link CycleContext#call}.
   */
  <R extends @Nullable Object> FutureValue<R> query(ServantFunction<? super S, R> query);

  /**
   * Requests that {@code reaction} be added under {@code name}, after the reactions already there;
   * a reaction of that name already there is replaced in place (and the values it awaited are
   * cancelled).
   */
  void addReaction(String name, Reaction<S> reaction);

  /**
   * Requests that the reaction {@code name} be removed; the values it awaits are {@link
   * AwaitedValue.Status#CANCELLED cancelled}. Removing a name that is not there is traced and
   * otherwise does nothing.
   */
  void removeReaction(String name);

  /**
   * Requests a change of the state, applied like the other requests ({@code setScheduling}, {@code
   * changeModule} in MAAM).
   *
   * @param description what the change is, for the trace
   */
  void adapt(String description, Consumer<? super S> change);

  /**
   * Requests that the entity answer the {@link org.armgals.active.Request}s sent to it with {@code
   * answer}, replacing the one before; applied like the other requests. Until then a request is
   * refused: the asker's value fails with {@link UnsupportedOperationException}.
   */
  void answerWith(Answer<S> answer);

  /** The names of its reactions, in running order, as of the last adaptation point. */
  List<String> reactions();
}

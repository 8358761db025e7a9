package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * An event that activates a method of the receiver's servant (paper §4.1, interface {@code
 * Callable}).
 *
 * <p>The receiving object calls {@link #setServant} once, when it first looks at the request, then
 * {@link #guard()} (through {@link #isProcessable()}) as often as needed, then {@link #apply()}
 * exactly once, all from the receiving object. Use {@link MethodRequest} or {@link
 * SynchronizedMethodRequest} rather than implementing this interface directly; they keep the
 * servant binding and the reply.
 *
 * @param <S> the servant type
 * @param <R> the result type ({@link Void} for a one-way request)
 */
public interface Callable<S, R> extends Event {

  /**
   * Binds the servant this request applies to. Called once by the receiving object, on its own
   * thread, before it first evaluates the guard.
   */
  void setServant(S servant);

  /** Whether the bound servant's state allows this request to run now. */
  boolean guard();

  /**
   * Runs the request on the bound servant.
   *
   * @return the result (sent back through the request's future when it is synchronized)
   * @throws Exception anything the servant throws; it completes the request's future exceptionally
   *     and goes to the runtime's error handler
   */
  @Nullable R apply() throws Exception;

  @Override
  default boolean isProcessable() {
    return guard();
  }
}

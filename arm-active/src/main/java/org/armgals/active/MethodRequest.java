package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * An unsynchronized method request (paper §4.1, class {@code MethodRequest}): one-way code run on
 * the receiver's servant once its guard holds. Subclass it and override {@link #invoke} (and {@link
 * #guard(Object)} for a guarded request); send it with {@link ActiveRef#send(Event)}. A request is
 * sent once; most code uses {@link ActiveRef#send(ServantAction)} instead.
 *
 * @param <S> the servant type
 */
public abstract class MethodRequest<S> extends ServantRequest<S> implements Callable<S, Void> {

  /** For subclasses. */
  protected MethodRequest() {}

  @Override
  public final @Nullable Void apply() throws Exception {
    invoke(servant());
    return null;
  }

  /** The request's work, on the receiver's thread. */
  protected abstract void invoke(S servant) throws Exception;

  @Override
  final void run() throws Exception {
    apply();
  }
}

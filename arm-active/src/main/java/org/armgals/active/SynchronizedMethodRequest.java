package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * A synchronized method request (paper §4.1, class {@code SynchronizedMethodRequest}): code run on
 * the receiver's servant whose result, or failure, completes a future in the sender. Subclass it
 * and override {@link #invoke} (and {@link #guard(Object)}); send it with {@link
 * ActiveRef#call(SynchronizedMethodRequest)}. Most code uses {@link
 * ActiveRef#call(ServantFunction)} instead.
 *
 * @param <S> the servant type
 * @param <R> the result type
 */
public abstract class SynchronizedMethodRequest<S, R extends @Nullable Object>
    extends ServantRequest<S> implements Callable<S, R> {
  private @Nullable Reply<R> reply;

  /** For subclasses. */
  protected SynchronizedMethodRequest() {}

  @Override
  public final R apply() throws Exception {
    return invoke(servant());
  }

  /** The request's work, on the receiver's thread; its result completes the sender's future. */
  protected abstract R invoke(S servant) throws Exception;

  final void reply(Reply<R> r) {
    this.reply = r;
  }

  @Override
  final void run() throws Exception {
    R value = apply();
    Reply<R> r = reply;
    if (r != null) {
      r.complete(value);
    }
  }

  @Override
  final void abandon(ActiveException cause) {
    Reply<R> r = reply;
    if (r != null) {
      r.abandon(cause);
    }
  }

  @Override
  final void failed(Throwable cause) {
    Reply<R> r = reply;
    if (r != null) {
      r.fail(cause);
    }
  }
}

package org.armgals.active;

import static java.util.Objects.requireNonNull;

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
public abstract class SynchronizedMethodRequest<S, R extends @Nullable Object> extends Envelope
    implements Callable<S, R> {
  private @Nullable S servant;
  private @Nullable Reply<R> reply;

  /** For subclasses. */
  protected SynchronizedMethodRequest() {}

  @Override
  public final void setServant(S servant) {
    this.servant = requireNonNull(servant, "servant");
  }

  @Override
  public final boolean guard() {
    return guard(servant());
  }

  @Override
  public final R apply() throws Exception {
    return invoke(servant());
  }

  /** Whether the servant's state lets the request run; default {@code true}. */
  protected boolean guard(S servant) {
    return true;
  }

  /** The request's work, on the receiver's thread; its result completes the sender's future. */
  protected abstract R invoke(S servant) throws Exception;

  private S servant() {
    S s = servant;
    if (s == null) {
      throw new IllegalStateException("no servant: the request has not been queued yet");
    }
    return s;
  }

  final void reply(Reply<R> r) {
    this.reply = r;
  }

  @Override
  @SuppressWarnings("unchecked")
  final boolean processable(Object servant) {
    if (this.servant == null) {
      setServant((S) servant);
    }
    return guard();
  }

  @Override
  @SuppressWarnings("unchecked")
  final void process(Core<?> receiver) throws Exception {
    if (this.servant == null) {
      setServant((S) receiver.servant());
    }
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

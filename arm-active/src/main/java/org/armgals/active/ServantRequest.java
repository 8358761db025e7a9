package org.armgals.active;

import static java.util.Objects.requireNonNull;

import org.jspecify.annotations.Nullable;

/**
 * What {@link MethodRequest} and {@link SynchronizedMethodRequest} share: the servant binding of
 * the paper's {@code Callable} (bound by the receiving object when it first looks at the request)
 * and the guard in terms of that servant.
 *
 * @param <S> the servant type
 */
abstract class ServantRequest<S> extends Envelope {
  private @Nullable S servant;

  /** The object it was sent to; set once, when sent (a request object is sent at most once). */
  private @Nullable Core<?> to;

  @Override
  final boolean claim(Core<?> receiver) {
    if (to != null) {
      return false;
    }
    to = receiver;
    return true;
  }

  @Override
  final @Nullable Core<?> receiver() {
    return to;
  }

  /** Binds the servant; see {@link Callable#setServant}. */
  public final void setServant(S servant) {
    this.servant = requireNonNull(servant, "servant");
  }

  /** The guard on the bound servant; see {@link Callable#guard()}. */
  public final boolean guard() {
    return guard(servant());
  }

  /** Whether the servant's state lets the request run; default {@code true}. */
  protected boolean guard(S servant) {
    return true;
  }

  /** The bound servant. */
  final S servant() {
    S s = servant;
    if (s == null) {
      throw new IllegalStateException("no servant: the request has not been queued yet");
    }
    return s;
  }

  @SuppressWarnings("unchecked")
  private void bindTo(Object receiverServant) {
    if (servant == null) {
      setServant((S) receiverServant);
    }
  }

  @Override
  final boolean processable(Object servant) {
    bindTo(servant);
    return guard();
  }

  @Override
  final void process(Core<?> receiver) throws Exception {
    bindTo(receiver.servant());
    run();
  }

  /** Applies the request to the bound servant and delivers what it gives. */
  abstract void run() throws Exception;
}

package org.armgals.active;

import static java.util.Objects.requireNonNull;

import org.jspecify.annotations.Nullable;

/**
 * An unsynchronized method request (paper §4.1, class {@code MethodRequest}): one-way code run on
 * the receiver's servant once its guard holds. Subclass it and override {@link #invoke} (and {@link
 * #guard(Object)} for a guarded request); send it with {@link ActiveRef#send(Event)}. A request is
 * sent once; most code uses {@link ActiveRef#send(ServantAction)} instead.
 *
 * @param <S> the servant type
 */
public abstract class MethodRequest<S> extends Envelope implements Callable<S, Void> {
  private @Nullable S servant;

  /** For subclasses. */
  protected MethodRequest() {}

  @Override
  public final void setServant(S servant) {
    this.servant = requireNonNull(servant, "servant");
  }

  @Override
  public final boolean guard() {
    return guard(servant());
  }

  @Override
  public final @Nullable Void apply() throws Exception {
    invoke(servant());
    return null;
  }

  /** Whether the servant's state lets the request run; default {@code true}. */
  protected boolean guard(S servant) {
    return true;
  }

  /** The request's work, on the receiver's thread. */
  protected abstract void invoke(S servant) throws Exception;

  private S servant() {
    S s = servant;
    if (s == null) {
      throw new IllegalStateException("no servant: the request has not been queued yet");
    }
    return s;
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
    apply();
  }
}

package org.armgals.active;

/**
 * A {@link SynchronousFuture} was read before its {@link FutureEvent} arrived. Reactive objects
 * never wait: they test {@link Future#isDone()} at each instant (active wait, paper §5.2).
 */
public final class FutureNotAvailableException extends ActiveException {
  private static final long serialVersionUID = 1L;

  /** The reply from {@code object} has not arrived yet at {@code instant}. */
  public FutureNotAvailableException(String object, long instant) {
    super(
        "the reply from "
            + object
            + " is not available at instant "
            + instant
            + "; test isDone() and retry at a later instant");
  }
}

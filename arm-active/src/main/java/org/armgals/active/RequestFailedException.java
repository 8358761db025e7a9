package org.armgals.active;

/**
 * A synchronized request failed in its receiver: its servant threw (that exception is the
 * {@linkplain #getCause() cause}), or its guard threw (the cause is an {@link
 * IllegalStateException} whose own cause is the guard's exception). Thrown by {@link
 * Future#touch()} and {@link FutureValue#getValue()}.
 */
public final class RequestFailedException extends ActiveException {
  private static final long serialVersionUID = 1L;

  /** The servant of {@code object} threw {@code cause}. */
  public RequestFailedException(String object, Throwable cause) {
    super("request to " + object + " failed: " + cause, cause);
  }
}

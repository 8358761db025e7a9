package org.armgals.active;

/**
 * A synchronized request failed in its servant: thrown by {@link Future#touch()} and {@link
 * FutureValue#getValue()}; the servant's exception is the {@linkplain #getCause() cause}.
 */
public final class RequestFailedException extends ActiveException {
  private static final long serialVersionUID = 1L;

  /** The servant of {@code object} threw {@code cause}. */
  public RequestFailedException(String object, Throwable cause) {
    super("request to " + object + " failed: " + cause, cause);
  }
}

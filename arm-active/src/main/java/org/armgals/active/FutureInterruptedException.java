package org.armgals.active;

/**
 * The thread waiting by necessity was interrupted (for instance by a cancelling shutdown). The
 * thread's interrupt status is set again when this is thrown.
 */
public final class FutureInterruptedException extends ActiveException {
  private static final long serialVersionUID = 1L;

  /** The wait for a reply from {@code object} was interrupted. */
  public FutureInterruptedException(String object, InterruptedException cause) {
    super("interrupted while waiting for a reply from " + object, cause);
  }
}

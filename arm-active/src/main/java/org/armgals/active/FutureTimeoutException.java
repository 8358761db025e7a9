package org.armgals.active;

import java.time.Duration;

/** A wait by necessity ran out of time before the future was completed. */
public final class FutureTimeoutException extends ActiveException {
  private static final long serialVersionUID = 1L;

  /** The wait for a reply from {@code object} lasted {@code timeout}. */
  public FutureTimeoutException(String object, Duration timeout) {
    super("no reply from " + object + " within " + timeout);
  }
}

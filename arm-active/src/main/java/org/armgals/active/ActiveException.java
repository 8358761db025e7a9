package org.armgals.active;

import org.jspecify.annotations.Nullable;

/** The root of the exceptions the active-object runtime throws. */
public class ActiveException extends RuntimeException {
  private static final long serialVersionUID = 1L;

  /** With a message and an optional cause. */
  public ActiveException(String message, @Nullable Throwable cause) {
    super(message, cause);
  }

  /** With a message. */
  public ActiveException(String message) {
    super(message);
  }
}

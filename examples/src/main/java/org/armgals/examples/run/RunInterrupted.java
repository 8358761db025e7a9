package org.armgals.examples.run;

/**
 * A run stopped before its end because it was asked to (Ctrl-C), having kept what it had and said
 * so: {@code armgals} exits with {@code Armgals.INTERRUPTED} (130) and prints nothing more.
 */
public final class RunInterrupted extends RuntimeException {
  private static final long serialVersionUID = 1L;

  /** With a message for a log; the user has been told already. */
  public RunInterrupted(String message) {
    super(message);
  }
}

package org.armgals.representation;

/** The base of the exceptions of the representation families. */
public class RepresentationException extends RuntimeException {
  private static final long serialVersionUID = 1L;

  /** An exception with that message. */
  public RepresentationException(String message) {
    super(message);
  }
}

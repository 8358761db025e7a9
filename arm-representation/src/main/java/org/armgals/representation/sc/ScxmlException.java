package org.armgals.representation.sc;

import org.armgals.representation.RepresentationException;

/** An SCXML document that cannot be read: malformed, or outside the supported subset. */
public final class ScxmlException extends RepresentationException {
  private static final long serialVersionUID = 1L;
  private final int line;

  /**
   * The exception, its message prefixed with the line when it is known.
   *
   * @param message what is wrong, naming the element
   * @param line the line of the document it is on, or -1 when unknown
   */
  public ScxmlException(String message, int line) {
    super(line < 0 ? message : "line " + line + ": " + message);
    this.line = line;
  }

  /** The line of the document the problem is on, or -1 when unknown. */
  public int line() {
    return line;
  }
}

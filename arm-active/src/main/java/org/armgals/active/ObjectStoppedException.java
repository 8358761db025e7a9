package org.armgals.active;

/** An event was sent to, or a reply awaited from, an object that has been stopped. */
public final class ObjectStoppedException extends ActiveException {
  private static final long serialVersionUID = 1L;

  /** {@code object} is stopped. */
  public ObjectStoppedException(Address object) {
    super("active object " + object + " is stopped");
  }
}

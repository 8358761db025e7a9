package org.armgals.representation;

import static java.util.Objects.requireNonNull;

/** Thrown when a behavior is looked up, applied or deleted by a name no behavior has. */
public final class NoSuchBehaviorException extends RepresentationException {
  private static final long serialVersionUID = 1L;
  private final String name;

  /**
   * The exception, its message naming the missing behavior and those there are.
   *
   * @param name the missing behavior's name
   * @param known the names there are, for the message
   */
  public NoSuchBehaviorException(String name, Iterable<String> known) {
    super("no behavior named '" + requireNonNull(name, "name") + "'; known: " + known);
    this.name = name;
  }

  /** The name no behavior has. */
  public String name() {
    return name;
  }
}

package org.armgals.maam;

import java.util.List;

/**
 * A program whose module graph is not a DAG, refused: {@link #modules} is one cycle, each module
 * feeding the next and the last feeding the first.
 */
public final class CycleException extends IllegalArgumentException {

  private static final long serialVersionUID = 1L;

  /** The modules on the cycle. */
  @SuppressWarnings("serial") // an immutable List.copyOf
  private final List<String> modules;

  CycleException(String where, List<String> modules) {
    super(where + " is not a DAG: cycle " + String.join(" -> ", modules) + " -> " + modules.get(0));
    this.modules = List.copyOf(modules);
  }

  /** The modules on one cycle, in edge order, starting from the first in declaration order. */
  public List<String> modules() {
    return modules;
  }
}

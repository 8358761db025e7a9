package org.armgals.maam;

/**
 * A behavior module whose parameters its robot's meta may change while it runs ({@link
 * RobotKind#setParameter}): the module keeps its identity and state, only a parameter moves. The
 * robot calls {@link #tune} on its own thread, between two cycles (its adaptation point).
 */
public interface Tunable {

  /**
   * Sets {@code parameter} to {@code value}.
   *
   * @throws IllegalArgumentException an unknown parameter or a value out of its range, naming both:
   *     nothing changes, and the meta is told why
   */
  void tune(String parameter, Object value);
}

package org.armgals.examples.robots;

import java.util.Optional;
import org.armgals.maam.Signal;

/** The signals of {@link Reconfigure}'s modules. */
final class ReconfigureSignals {
  private ReconfigureSignals() {}

  /**
   * The rhythm of the crawl this cycle: the gait's phase (rad) and how much of the full stride to
   * take, from 0 to 1 (the head ramps it up at the start).
   */
  record Beat(double phase, double amplitude) implements Signal {}

  /** The beat the atom ahead sent last cycle through the front bond. */
  record Heard(double phase, double amplitude) implements Signal {}

  /**
   * What the atom's two chain legs are bound to, from its binding sensors: the body id of the atom
   * ahead (on +x) and behind (on −x), if any.
   */
  record Bonds(Optional<String> ahead, Optional<String> behind) implements Signal {}

  /** Both side legs see a wall this near (m): left (+y side) and right (−y side). */
  record Walls(double left, double right) implements Signal {}
}

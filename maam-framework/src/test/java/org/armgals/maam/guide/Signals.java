package org.armgals.maam.guide;

import org.armgals.maam.Signal;

/** Step 3: the signals between the balancing atom's modules. */
final class Signals {

  private Signals() {}

  // tag::signals[]
  /** The atom leans: how far, in radians, about x and y. */
  record Tilted(double roll, double pitch) implements Signal {}

  /** The battery is low: joules left. */
  record LowBattery(double joules) implements Signal {}

  /** How far every leg should open from its cone's axis, in radians. */
  record Stance(double elevation) implements Signal {}
  // end::signals[]
}

package org.armgals.examples.robots;

import org.armgals.maam.Port;
import org.armgals.maam.Signal;

/** The signals flowing in a caterpillar segment's cycle, and the ports that carry them. */
final class CaterpillarSignals {

  private CaterpillarSignals() {}

  /**
   * The rhythm the segment ahead sent through the bound leg: where it is in its wave, and the
   * wave's period and stride, which the head sets for the whole chain.
   *
   * @param phase the sender's phase in its step, in [0, 1)
   * @param period seconds per step
   * @param stride half the swing of a leg along the chain, radians
   */
  record Heard(double phase, double period, double stride) implements Signal {}

  /**
   * Where this segment is in its step.
   *
   * @param phase in [0, 1): stance (leg on the ground, pushing back) in the first half, swing in
   *     the second
   * @param period seconds per step
   * @param stride half the swing of the leg along the chain, radians
   */
  record Beat(double phase, double period, double stride) implements Signal {}

  /**
   * Where the feet's tips should be: their tilt from their cones' axes, radians, along the chain
   * ({@code along}, positive towards the head) and outwards, away from the chain ({@code out}).
   */
  record Stroke(double along, double out) implements Signal {}

  /** Where the segment is on the ground, metres: what the meta level watches. */
  record Travel(double x, double y) implements Signal {}

  static final Port<Heard> HEARD = Port.of("heard", Heard.class);
  static final Port<Beat> BEAT = Port.of("beat", Beat.class);
  static final Port<Stroke> STROKE = Port.of("stroke", Stroke.class);
  static final Port<Travel> TRAVEL = Port.of("travel", Travel.class);
}

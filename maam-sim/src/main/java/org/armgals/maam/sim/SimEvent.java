package org.armgals.maam.sim;

import org.armgals.maam.spi.Leg;

/**
 * Something that happened in a simulation, recorded in the trace of the control cycle it happened
 * in. Physical events come from the simulator; {@link Note}s come from the meta level.
 */
public sealed interface SimEvent {

  /** The virtual time it happened (ns). */
  long timeNanos();

  /** Two tips bound. */
  record Bound(long timeNanos, int atomA, Leg legA, int atomB, Leg legB) implements SimEvent {}

  /** A binding was released on command by {@code atomA}. */
  record Unbound(long timeNanos, int atomA, Leg legA, int atomB, Leg legB) implements SimEvent {}

  /** A binding broke under a force above its strength (N). */
  record BindingBroke(long timeNanos, int atomA, Leg legA, int atomB, Leg legB, double force)
      implements SimEvent {}

  /** An atom failed (fault injection). */
  record AtomFailed(long timeNanos, int atom) implements SimEvent {}

  /** A leg failed (fault injection). */
  record LegFailed(long timeNanos, int atom, Leg leg) implements SimEvent {}

  /** An atom's battery ran empty; its motors stopped. */
  record BatteryEmpty(long timeNanos, int atom) implements SimEvent {}

  /** A message through a binding was lost. */
  record MessageLost(long timeNanos, int from, Leg fromLeg) implements SimEvent {}

  /** Something the meta level saw or did, noted for the trace. */
  record Note(long timeNanos, int atom, String text) implements SimEvent {}
}

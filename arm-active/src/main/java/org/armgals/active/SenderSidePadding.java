package org.armgals.active;

import org.jspecify.annotations.Nullable;

/**
 * The fields between {@link ReceiverSide}'s and {@link SenderSide}'s: those that neither the
 * senders nor the receiving object touch on every event, then 20 bytes of padding, so that the
 * senders' fields start 72 bytes into the object. No line then holds both them and what lies before
 * the object (usually its servant, written on every event), and the senders' tail and size share a
 * line with the receiving side's fields at two of the eight places an object can start in a line
 * (ObjectLayoutTest). An idle object costs at most 100 bytes in all (decision 0045).
 */
abstract class SenderSidePadding extends ReceiverSide {
  /** The object's number in its runtime. */
  final long id;

  /** The object's runtime. */
  final RuntimeImpl runtime;

  /**
   * The buffer's first node: the last event taken, or this object itself. Consumer only; while an
   * activation runs, its carrier's cursor stands for it (written back when the activation ends), so
   * that taking an event writes nothing in the object.
   */
  Link head;

  /** The object's address, made on first use. */
  @Nullable Address address;

  @SuppressWarnings("unused")
  private int p1, p2, p3, p4, p5;

  SenderSidePadding(Object servant, RuntimeImpl runtime, long id) {
    super(servant);
    this.id = id;
    this.runtime = runtime;
    this.head = this;
  }
}

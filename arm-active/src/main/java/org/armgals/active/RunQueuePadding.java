package org.armgals.active;

/**
 * 64 bytes between a {@link RunQueue}'s two ends, so that no cache line holds both. A subclass's
 * fields are laid out after its superclass's, so the padding sits between them whatever order the
 * JVM gives the fields of one class. One queue per runtime: the bytes cost nothing.
 */
abstract class RunQueuePadding extends RunQueueConsumerSide {
  @SuppressWarnings("unused")
  private long p1, p2, p3, p4, p5, p6, p7, p8;
}

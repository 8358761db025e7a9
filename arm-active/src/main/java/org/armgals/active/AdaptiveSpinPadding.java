package org.armgals.active;

/**
 * 128 bytes before {@link AdaptiveSpin}'s fields. A worker's spin is allocated right after its
 * worker and writes its fields at every step of a spin: without this they share a cache line with
 * the worker's {@code next} and {@code running}, which other workers read. Unpadded, a spin that
 * wrote a field on every look ran ping-pong 7-25% slower than the hand-written loop (decision
 * 0060); decision 0072 measured the batched spin with this padding.
 */
@SuppressWarnings("unused") // padding: never read
abstract class AdaptiveSpinPadding {
  private long p00, p01, p02, p03, p04, p05, p06, p07;
  private long p10, p11, p12, p13, p14, p15, p16, p17;
}

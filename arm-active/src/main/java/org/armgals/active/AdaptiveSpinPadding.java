package org.armgals.active;

/**
 * 128 bytes before {@link AdaptiveSpin}'s fields. A worker's spin is allocated right after its
 * worker and writes its step count on every step: without this it shares a cache line with the
 * worker's {@code next} and {@code running}, which other workers read, and ping-pong ran 7-25%
 * slower than with the same loop's counters in registers (decision 0060).
 */
@SuppressWarnings("unused") // padding: never read
abstract class AdaptiveSpinPadding {
  private long p00, p01, p02, p03, p04, p05, p06, p07;
  private long p10, p11, p12, p13, p14, p15, p16, p17;
}

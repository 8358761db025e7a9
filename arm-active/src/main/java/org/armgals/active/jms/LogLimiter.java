package org.armgals.active.jms;

import java.util.concurrent.atomic.AtomicLong;

/**
 * Lets one kind of repeated log line through at a bounded rate, so that a flood of bad input or a
 * long outage cannot flood the log: the first {@value #FIRST} occurrences, then one in {@value
 * #EVERY}; the line logged carries the count, so nothing is hidden. Thread-safe.
 */
final class LogLimiter {
  static final long FIRST = 20;
  static final long EVERY = 1_000;

  private final AtomicLong count = new AtomicLong();

  /** Counts one occurrence; its number if it should be logged, 0 otherwise. */
  long tick() {
    long n = count.incrementAndGet();
    return n <= FIRST || n % EVERY == 0 ? n : 0;
  }
}

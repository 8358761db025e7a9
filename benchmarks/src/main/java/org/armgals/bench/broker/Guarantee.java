package org.armgals.bench.broker;

/**
 * The delivery guarantee a run asks of both sides: at most once (non-persistent messages to plain
 * subscriptions, on the broker without a journal) or at least once (persistent messages with
 * Artemis's duplicate-detection id to shared durable subscriptions, on the broker with a journal).
 */
enum Guarantee {
  /** At most once: armgals' default. */
  AMO,
  /** At least once with duplicates suppressed. */
  ALO;

  String label() {
    return name().toLowerCase(java.util.Locale.ROOT);
  }
}

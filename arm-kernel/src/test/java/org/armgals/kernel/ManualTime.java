package org.armgals.kernel;

import java.time.Duration;
import java.util.concurrent.atomic.AtomicLong;
import org.armgals.active.TimeSource;

/** A time source advanced by hand. */
final class ManualTime implements TimeSource {
  private final AtomicLong now = new AtomicLong(1_000_000_000L);

  @Override
  public long nanoTime() {
    return now.get();
  }

  void advance(Duration d) {
    now.addAndGet(d.toNanos());
  }
}

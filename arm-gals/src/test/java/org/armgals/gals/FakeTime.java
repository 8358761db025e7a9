package org.armgals.gals;

import java.time.Duration;
import java.util.concurrent.atomic.AtomicLong;
import org.armgals.active.TimeSource;
import org.armgals.active.spi.DeadlinePacer;

/** A time source moved by the test (and by reactions that pretend to work for a while). */
final class FakeTime implements TimeSource {
  private final AtomicLong now = new AtomicLong();

  @Override
  public long nanoTime() {
    return now.get();
  }

  void advance(Duration d) {
    now.addAndGet(d.toNanos());
  }

  /** The pacer of a real-time runner on this time: parking is moving time forward. */
  DeadlinePacer pacing() {
    return DeadlinePacer.of(this, Duration.ZERO, now::addAndGet);
  }
}

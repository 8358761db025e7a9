package org.armgals.maam.sim.spi;

import java.util.function.LongConsumer;
import org.armgals.active.TimeSource;

/** The one place the simulator waits for real time; see {@link Pacer#realTime}. */
final class RealTimePacer implements Pacer {

  private final TimeSource time;
  private final LongConsumer sleeper;
  private final double speed;
  private long origin;
  private boolean started;

  RealTimePacer(TimeSource time, LongConsumer sleeper, double speed) {
    this.time = time;
    this.sleeper = sleeper;
    this.speed = speed;
  }

  @Override
  public void pace(long virtualNanos) {
    long now = time.nanoTime();
    if (!started) {
      started = true;
      origin = now - (long) (virtualNanos / speed);
      return;
    }
    long due = origin + (long) (virtualNanos / speed);
    if (due > now) {
      sleeper.accept(due - now);
    }
  }
}

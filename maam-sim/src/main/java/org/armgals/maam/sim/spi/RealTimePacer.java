package org.armgals.maam.sim.spi;

import org.armgals.active.spi.DeadlinePacer;

/** The one place the simulator waits for real time; see {@link Pacer#realTime}. */
final class RealTimePacer implements Pacer {

  private final DeadlinePacer pacer;
  private final double speed;
  private long origin;
  private boolean started;

  RealTimePacer(DeadlinePacer pacer, double speed) {
    this.pacer = pacer;
    this.speed = speed;
  }

  @Override
  public void pace(long virtualNanos) {
    if (!started) {
      started = true;
      origin = pacer.time().nanoTime() - (long) (virtualNanos / speed);
      return;
    }
    pacer.awaitUntil(origin + (long) (virtualNanos / speed));
  }
}

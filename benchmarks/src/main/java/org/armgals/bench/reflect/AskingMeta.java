package org.armgals.bench.reflect;

import java.time.Duration;
import org.armgals.kernel.Damping;
import org.armgals.kernel.Notification;
import org.armgals.kernel.spi.MetaContext;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.RobotKind;

/**
 * The meta level of {@link Asking}: on the notification of every {@code every}-th cycle of the
 * robot's time it asks for the dial to be set to that cycle ({@code setParameter}), with a damping
 * (a dwell of half that many cycles, a generous rate limit) that lets every request through, so
 * that a run of a few seconds makes hundreds of requests to time.
 */
final class AskingMeta extends BMetaRobot {
  private final long periodNanos;
  private final int every;

  AskingMeta(long periodNanos, int every) {
    super(
        "bmasking",
        new Damping(Duration.ofNanos(periodNanos * every / 2), 1_000, Duration.ofSeconds(1)));
    if (every < 2) {
      throw new IllegalArgumentException("asks every " + every + " cycles: expected >= 2");
    }
    this.periodNanos = periodNanos;
    this.every = every;
  }

  @Override
  public void onNotification(MetaContext context, Notification notification) {
    long cycle = Math.floorDiv(notification.nanoTime(), periodNanos);
    if (cycle > 0 && cycle % every == 0) {
      context.adapt(
          notification.entity(),
          RobotKind.because(
              "cycle " + cycle,
              RobotKind.setParameter(AskingRobot.DIAL, AskingRobot.SETTING, cycle)));
    }
  }
}

package org.armgals.maam.spi;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Where a robot sends the failures of its cycle: a module's step, its behavioral meta's
 * notification. The robot counts them too, and goes on with the cycle.
 *
 * <p>Threading: called on the robot's thread; must not throw.
 */
@FunctionalInterface
public interface RobotErrorHandler {

  /**
   * {@code robot} failed in {@code where} (a module's name, or {@code "bmeta"}) with {@code error}.
   */
  void onError(String robot, String where, Throwable error);

  /** Logs each failure through SLF4J at WARN, with the stack trace. The default. */
  static RobotErrorHandler logging() {
    Logger log = LoggerFactory.getLogger("org.armgals.maam");
    return (robot, where, error) -> log.warn("robot {} failed in {}", robot, where, error);
  }
}

package org.armgals.examples.robots;

import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.armgals.kernel.Damping;
import org.armgals.kernel.Entity;
import org.armgals.kernel.Notification;
import org.armgals.kernel.spi.MetaContext;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.RobotKind;

/**
 * The behavioral meta level of {@link ObstacleRobot}'s chain, a behavioral meta-entity of the
 * kernel taking every atom, notified by the front atom's states: its model is the front atom's
 * progress over a sliding window. When the chain has gained less than {@value #MIN_GAIN} m for
 * {@value #WINDOW_SECONDS} s (pushing against the step, the climb reflex looping without gain), it
 * locates the step's edge just ahead of the front atom and asks every atom to add the lift-front
 * schema from their kind's catalog, with its connectors, once, saying why.
 *
 * <p>Threading: runs on its meta-entity's own object, never on an atom's thread, in the chain's JVM
 * or another.
 */
final class ObstacleMeta extends BMetaRobot {
  static final double WINDOW_SECONDS = 2.0;
  static final double MIN_GAIN = 0.02;

  /** From the front kernel's centre to the step's face when the chain stalls (m). */
  static final double EDGE_AHEAD = 0.005;

  private final String front;
  private long windowStart = -1;
  private double windowX;
  private volatile boolean adapted;

  /**
   * @param front the name of the front atom's robot, whose progress it watches
   */
  ObstacleMeta(String front) {
    super("bmchain", Damping.none());
    this.front = front;
  }

  /** Whether it has asked for the lift-front schema. */
  boolean adapted() {
    return adapted;
  }

  @Override
  public void onNotification(MetaContext context, Notification n) {
    if (adapted || !context.entity(n.entity()).name().equals(front)) {
      return;
    }
    Map<String, Object> seen = observation(n).orElse(Map.of());
    if (!(seen.get(ObstacleAtom.X) instanceof Double x)) {
      return;
    }
    long now = context.nanoTime();
    if (windowStart < 0 || x - windowX > MIN_GAIN) {
      windowStart = now;
      windowX = x;
      return;
    }
    double stalled = (now - windowStart) / 1e9;
    if (stalled < WINDOW_SECONDS) {
      return;
    }
    adapted = true;
    double edge = x + EDGE_AHEAD;
    String why =
        String.format(
            Locale.ROOT,
            "no progress for %.1f s (gained %.1f cm): a step at x = %.2f m",
            stalled,
            100 * (x - windowX),
            edge);
    for (Entity atom : context.self().baseLevelEntities()) {
      context.adapt(
          atom.address(),
          RobotKind.because(
              why, RobotKind.addSchema(ObstacleAtom.LIFT_FRONT, Map.of(ObstacleAtom.EDGE, edge))));
      for (String connector : ObstacleAtom.LIFT_FRONT_CONNECTORS) {
        context.adapt(
            atom.address(), RobotKind.because(why, RobotKind.addConnector(connector, Map.of())));
      }
    }
  }

  /** The names of the atoms' robots, rear first, that it takes. */
  static List<String> robots(int atoms) {
    return java.util.stream.IntStream.range(0, atoms).mapToObj(i -> "atom-" + i).toList();
  }
}

package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import org.armgals.examples.robots.ObstacleSignals.Position;
import org.armgals.examples.sim.Journal;
import org.armgals.maam.Adaptation;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.CycleReport;

/**
 * The behavioral meta level of {@link ObstacleRobot}'s chain, notified by the front atom's robot:
 * its model is the front atom's progress over a sliding window (from the odometry signals in the
 * cycle reports). When the chain has gained less than {@value #MIN_GAIN} m for {@value
 * #WINDOW_SECONDS} s (pushing against the step, the climb reflex looping without gain), it locates
 * the step's edge just ahead of the front atom and adds the lift-front schema to every atom's
 * robot, once, telling the journal what and why.
 */
final class ObstacleMeta implements BMetaRobot {
  static final double WINDOW_SECONDS = 2.0;
  static final double MIN_GAIN = 0.02;

  /** From the front kernel's centre to the step's face when the chain stalls (m). */
  static final double EDGE_AHEAD = 0.005;

  private final Journal journal;
  private final List<ObstacleAtom> robots = new ArrayList<>();
  private final List<Integer> atomIds = new ArrayList<>();
  private long windowStart = -1;
  private double windowX;
  private boolean adapted;

  ObstacleMeta(Journal journal) {
    this.journal = requireNonNull(journal, "journal");
  }

  /** Adds the robot of the next atom of the chain, rear first; the last is the front. */
  void watch(int atomId, ObstacleAtom robot) {
    atomIds.add(atomId);
    robots.add(requireNonNull(robot, "robot"));
  }

  /** Whether it has added the lift-front schema. */
  boolean adapted() {
    return adapted;
  }

  @Override
  public void onCycle(CycleReport report, Consumer<Adaptation> requests) {
    Position position = null;
    for (CycleReport.Emission e : report.emissions()) {
      if (e.signal() instanceof Position p) {
        position = p;
      }
    }
    if (position == null || adapted) {
      return;
    }
    long now = report.nanoTime();
    if (windowStart < 0 || position.x() - windowX > MIN_GAIN) {
      windowStart = now;
      windowX = position.x();
      return;
    }
    double stalled = (now - windowStart) / 1e9;
    if (stalled < WINDOW_SECONDS) {
      return;
    }
    adapted = true;
    double edge = position.x() + EDGE_AHEAD;
    String why =
        String.format(
            Locale.ROOT,
            "no progress for %.1f s (gained %.1f cm): a step at x = %.2f m",
            stalled,
            100 * (position.x() - windowX),
            edge);
    ObstacleAtom front = robots.get(robots.size() - 1);
    for (int i = 0; i < robots.size(); i++) {
      ObstacleAtom robot = robots.get(i);
      for (Adaptation a : robot.liftFront(edge)) {
        if (robot == front) {
          requests.accept(a);
        } else {
          robot.request(a);
        }
      }
      journal.adaptation(atomIds.get(i), "added schema " + ObstacleAtom.LIFT_FRONT, why);
    }
  }
}

package org.armgals.examples.robots;

import static org.armgals.examples.robots.WalkerSignals.FOOTING;
import static org.armgals.examples.robots.WalkerSignals.JOINTS;
import static org.armgals.examples.robots.WalkerSignals.TARGETS;
import static org.armgals.examples.robots.WalkerSignals.TIPPING;

import java.time.Duration;
import java.util.Map;
import org.armgals.active.TimeSource;
import org.armgals.examples.robots.WalkerModules.Balance;
import org.armgals.examples.robots.WalkerModules.Drive;
import org.armgals.examples.robots.WalkerModules.Feet;
import org.armgals.examples.robots.WalkerModules.Gait;
import org.armgals.examples.robots.WalkerModules.Lean;
import org.armgals.examples.robots.WalkerModules.Odometer;
import org.armgals.examples.robots.WalkerModules.ReadJoints;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.StructuralMeta;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.Emission;
import org.armgals.maam.PortRef;
import org.armgals.maam.RobotKind;
import org.armgals.maam.Schema;
import org.armgals.maam.Suppressor;
import org.armgals.maam.spi.Body;
import org.armgals.representation.p.PState;

/**
 * The walker's program (paper §5.4): two schemas joined by subsumption.
 *
 * <pre>
 *   walk:    joints --joints--\
 *            feet ---footing---> gait --targets--(S)--> drive
 *            odometer --course--> (the meta level)           ^
 *   balance: lean --tipping--> balance --targets-------------/ suppresses gait's targets
 * </pre>
 *
 * Balancing wins over walking: while the atom leans too far, and for {@link
 * WalkerTuning#BALANCE_HOLD} after, the balance reflex's targets replace the gait's. Stepped by the
 * simulation's controller, one cycle per control period, as a kernel entity whose meta level
 * watches its course and its balance reflex ({@link #observe()}).
 */
final class WalkerRobot extends AbstractRobot {

  WalkerRobot(Body body, TimeSource time, double cycleSeconds) {
    super("walker", body, time);
    ReadJoints joints = new ReadJoints("joints");
    Feet feet = new Feet("feet");
    Odometer odometer = new Odometer("odometer");
    Gait gait = new Gait("gait", cycleSeconds);
    Drive drive = new Drive("drive");
    addSchema(
        Schema.builder("walk")
            .add(joints)
            .add(feet)
            .add(odometer)
            .add(gait)
            .add(drive)
            .wire(joints, JOINTS, gait, JOINTS)
            .wire(feet, FOOTING, gait, FOOTING)
            .wire(gait, TARGETS, drive, TARGETS)
            .build());
    Lean lean = new Lean("lean", WalkerTuning.LEAN_LIMIT);
    Balance balance = new Balance("balance");
    addSchema(
        Schema.builder("balance")
            .add(lean)
            .add(balance)
            .wire(lean, TIPPING, balance, TIPPING)
            .build());
    addConnector(
        new Suppressor(
            PortRef.of(balance, TARGETS),
            PortRef.of(gait, TARGETS),
            Duration.ofNanos(Math.round(WalkerTuning.BALANCE_HOLD * 1e9))));
  }

  /** Whether the balance reflex drove the legs in the last cycle (observed). */
  static final String BALANCING = "balancing";

  /** Where the odometer put the atom in the last cycle, metres (observed). */
  static final String X = "x";

  /** Where the odometer put the atom in the last cycle, metres (observed). */
  static final String Y = "y";

  /** The walker's kind, {@code WalkerRobot}: it observes its course and its balance reflex. */
  static StructuralMeta<PState> kind(Kernel kernel) {
    return RobotKind.builder("WalkerRobot", WalkerRobot.class)
        .observing(Map.of(BALANCING, false, X, 0.0, Y, 0.0))
        .define(kernel);
  }

  /** What the walker shows its meta level: the robot's own, its course, its balance reflex. */
  @Override
  protected Map<String, Object> observe() {
    Map<String, Object> m = super.observe();
    boolean balancing = false;
    double x = 0;
    double y = 0;
    for (Emission e : emissions()) {
      if (e.port().module().equals("balance") && e.port().port().equals(TARGETS)) {
        balancing = true;
      } else if (e.signal() instanceof WalkerSignals.Course course) {
        x = course.x();
        y = course.y();
      }
    }
    m.put(BALANCING, balancing);
    m.put(X, x);
    m.put(Y, y);
    return m;
  }
}

package org.armgals.examples.robots;

import static org.armgals.examples.robots.EnergySignals.POSE;
import static org.armgals.examples.robots.EnergySignals.STRIDE;

import java.util.Map;
import org.armgals.active.TimeSource;
import org.armgals.examples.robots.EnergyModules.Battery;
import org.armgals.examples.robots.EnergyModules.LegDrive;
import org.armgals.examples.robots.EnergyModules.LegSensor;
import org.armgals.examples.robots.EnergyModules.Stepper;
import org.armgals.examples.robots.EnergySignals.EnergyLevel;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.StructuralMeta;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.Emission;
import org.armgals.maam.RobotKind;
import org.armgals.maam.Schema;
import org.armgals.maam.spi.Body;
import org.armgals.representation.p.PState;

/**
 * The base level of the {@link EnergySaver}: two schemas, <i>gait</i> (legs → stepper → drive) and
 * <i>energy</i> (the battery perceptor). A kernel entity that shows its meta level the energy left
 * ({@link #observe()}: {@value #JOULES} and {@value #FRACTION} of a full battery), on an island the
 * simulation's controller steps once per control period; it adapts at the end of a cycle.
 */
final class EnergyRobot extends AbstractRobot {
  static final String STEPPER = "stepper";

  /** The observed energy left, J. */
  static final String JOULES = "joules";

  /** The observed fraction of a full battery left, in [0, 1]. */
  static final String FRACTION = "fraction";

  /** The stepper's gait in a request: {@code fast} or {@code saving}. */
  static final String GAIT = "gait";

  private final double periodSeconds;

  EnergyRobot(Body body, TimeSource time, double periodSeconds, double capacity) {
    super("energy", body, time);
    this.periodSeconds = periodSeconds;
    LegSensor legs = new LegSensor("legs");
    Stepper stepper = new Stepper(STEPPER, EnergyGait.FAST, periodSeconds);
    LegDrive drive = new LegDrive("drive");
    addSchema(
        Schema.builder("gait")
            .add(legs)
            .add(stepper)
            .add(drive)
            .wire(legs, POSE, stepper, POSE)
            .wire(stepper, STRIDE, drive, STRIDE)
            .build());
    addSchema(Schema.builder("energy").add(new Battery("battery", capacity)).build());
  }

  /**
   * The kind of the energy robot, {@code EnergyRobot}: it observes the energy left, and its catalog
   * has the {@value #STEPPER} of a {@value #GAIT}, {@code fast} or {@code saving}.
   */
  static StructuralMeta<PState> kind(Kernel kernel) {
    return RobotKind.builder("EnergyRobot", EnergyRobot.class)
        .observing(Map.of(JOULES, 0.0, FRACTION, 1.0))
        .module(
            STEPPER, (robot, p) -> new Stepper(STEPPER, gait(p.text(GAIT)), robot.periodSeconds))
        .define(kernel);
  }

  private static EnergyGait gait(String name) {
    for (EnergyGait g : new EnergyGait[] {EnergyGait.FAST, EnergyGait.SAVING}) {
      if (g.name().equals(name)) {
        return g;
      }
    }
    throw new IllegalArgumentException("gait '" + name + "': expected fast or saving");
  }

  /** What the robot shows its meta level: the robot's own, and the energy its battery reads. */
  @Override
  protected Map<String, Object> observe() {
    Map<String, Object> m = super.observe();
    double joules = 0;
    double fraction = 1;
    for (Emission e : emissions()) {
      if (e.signal() instanceof EnergyLevel level) {
        joules = level.joules();
        fraction = level.fraction();
      }
    }
    m.put(JOULES, joules);
    m.put(FRACTION, fraction);
    return m;
  }
}

package org.armgals.examples.robots;

import static org.armgals.examples.robots.EnergySignals.POSE;
import static org.armgals.examples.robots.EnergySignals.STRIDE;

import org.armgals.active.TimeSource;
import org.armgals.examples.robots.EnergyModules.Battery;
import org.armgals.examples.robots.EnergyModules.LegDrive;
import org.armgals.examples.robots.EnergyModules.LegSensor;
import org.armgals.examples.robots.EnergyModules.Stepper;
import org.armgals.kernel.AdaptationPoint;
import org.armgals.kernel.Threshold;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.Schema;
import org.armgals.maam.spi.Body;

/**
 * The base level of the {@link EnergySaver}: two schemas, <i>gait</i> (legs → stepper → drive) and
 * <i>energy</i> (the battery perceptor, whose energy events and threshold meta-events go to the
 * behavioral meta in each cycle's report). Stepped by the simulation's controller, one cycle per
 * control period; adapts at the end of a cycle.
 */
final class EnergyRobot extends AbstractRobot {
  static final String STEPPER = "stepper";

  EnergyRobot(
      Body body,
      TimeSource time,
      double periodSeconds,
      double capacity,
      Threshold threshold,
      BMetaRobot meta) {
    this(body, time, periodSeconds, capacity, threshold);
    setBehavioralMeta(meta);
  }

  EnergyRobot(
      Body body, TimeSource time, double periodSeconds, double capacity, Threshold threshold) {
    super("energy", body, time);
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
    addSchema(Schema.builder("energy").add(new Battery("battery", capacity, threshold)).build());
    setAdaptationPoint(AdaptationPoint.END_OF_CYCLE);
  }
}

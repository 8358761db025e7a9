package org.armgals.examples.robots;

import static org.armgals.examples.robots.CaterpillarSignals.BEAT;
import static org.armgals.examples.robots.CaterpillarSignals.HEARD;
import static org.armgals.examples.robots.CaterpillarSignals.STROKE;

import org.armgals.active.TimeSource;
import org.armgals.examples.robots.CaterpillarModules.Feet;
import org.armgals.examples.robots.CaterpillarModules.Listen;
import org.armgals.examples.robots.CaterpillarModules.Odometer;
import org.armgals.examples.robots.CaterpillarModules.Pacemaker;
import org.armgals.examples.robots.CaterpillarModules.Relay;
import org.armgals.examples.robots.CaterpillarModules.Step;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.Schema;
import org.armgals.maam.spi.Body;

/**
 * The program every segment of a caterpillar runs (paper §5.4): one schema, <i>wave</i>,
 *
 * <pre>
 *   listen --heard--> pacemaker --beat--> step --stroke--> feet
 *                                  \-beat--> relay (to the segment behind)
 *   odometer --travel--> (the meta level)
 * </pre>
 *
 * The head beats the rhythm; each segment hears it through its front leg's binding and passes it on
 * through its back leg, a quarter step later: a wave runs down the chain. Stepped by the
 * simulation's controller, one cycle per control period.
 */
final class CaterpillarSegment extends AbstractRobot {
  static final String PACEMAKER = "pacemaker";

  private final Pacemaker pacemaker;

  /**
   * @param fromHead the segment's place from the head, 0 first
   * @param cycleSeconds the control period
   */
  CaterpillarSegment(String name, Body body, TimeSource time, int fromHead, double cycleSeconds) {
    super(name, body, time);
    Listen listen = new Listen("listen");
    Odometer odometer = new Odometer("odometer");
    pacemaker =
        new Pacemaker(
            PACEMAKER,
            CaterpillarTuning.PERIOD,
            CaterpillarTuning.START_STRIDE,
            CaterpillarTuning.LAG,
            cycleSeconds,
            -fromHead * CaterpillarTuning.LAG);
    Step step = new Step("step");
    Feet feet = new Feet("feet");
    Relay relay = new Relay("relay");
    addSchema(
        Schema.builder("wave")
            .add(listen)
            .add(odometer)
            .add(pacemaker)
            .add(step)
            .add(feet)
            .add(relay)
            .wire(listen, HEARD, pacemaker, HEARD)
            .wire(pacemaker, BEAT, step, BEAT)
            .wire(pacemaker, BEAT, relay, BEAT)
            .wire(step, STROKE, feet, STROKE)
            .build());
  }

  /** The pacemaker the segment was built with (a meta level may have changed it since). */
  Pacemaker builtPacemaker() {
    return pacemaker;
  }

  /** Lets {@code meta} watch and adapt this segment. */
  void watchedBy(BMetaRobot meta) {
    setBehavioralMeta(meta);
  }
}

package org.armgals.examples.robots;

import static org.armgals.examples.robots.CaterpillarSignals.BEAT;
import static org.armgals.examples.robots.CaterpillarSignals.HEARD;
import static org.armgals.examples.robots.CaterpillarSignals.STROKE;
import static org.armgals.examples.robots.CaterpillarSignals.TRAVEL;

import java.util.Map;
import org.armgals.active.TimeSource;
import org.armgals.examples.robots.CaterpillarModules.Feet;
import org.armgals.examples.robots.CaterpillarModules.Listen;
import org.armgals.examples.robots.CaterpillarModules.Odometer;
import org.armgals.examples.robots.CaterpillarModules.Pacemaker;
import org.armgals.examples.robots.CaterpillarModules.Relay;
import org.armgals.examples.robots.CaterpillarModules.Step;
import org.armgals.examples.robots.CaterpillarSignals.Beat;
import org.armgals.examples.robots.CaterpillarSignals.Travel;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.StructuralMeta;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.Emission;
import org.armgals.maam.RobotKind;
import org.armgals.maam.Schema;
import org.armgals.maam.spi.Body;
import org.armgals.representation.p.PState;

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
 * through its back leg, a quarter step later: a wave runs down the chain. A kernel entity on an
 * island of its own, which the simulation's controller steps once per control period; it shows its
 * meta level the phase of its beat and how far it has travelled ({@link #observe()}).
 */
final class CaterpillarSegment extends AbstractRobot {
  static final String PACEMAKER = "pacemaker";

  /** The observed phase of the beat, in [0, 1); -1 before the first beat. */
  static final String PHASE = "phase";

  /** The observed distance travelled along x, metres. */
  static final String X = "x";

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

  /**
   * The kind of the segments, {@code CaterpillarSegment}, in {@code kernel}: they observe the phase
   * of their beat and their travel, and its catalog has the {@value #PACEMAKER}, built with a
   * {@value #STRIDE} (radians) from a {@value #PHASE} as a copy of the one the segment was built
   * with, which the head's meta level asks for.
   */
  static StructuralMeta<PState> kind(Kernel kernel) {
    return RobotKind.builder("CaterpillarSegment", CaterpillarSegment.class)
        .observing(Map.of(PHASE, -1.0, X, 0.0))
        .module(
            PACEMAKER,
            (segment, p) -> segment.pacemaker.withStride(p.number(STRIDE), p.number(PHASE)))
        .define(kernel);
  }

  /** The pacemaker's stride in a request, radians. */
  static final String STRIDE = "stride";

  /** What a segment shows its meta level: the robot's own, its beat's phase, its travel. */
  @Override
  protected Map<String, Object> observe() {
    Map<String, Object> m = super.observe();
    double phase = -1;
    double x = 0;
    for (Emission e : emissions()) {
      if (e.port().port().equals(BEAT) && e.signal() instanceof Beat beat) {
        phase = beat.phase();
      } else if (e.port().port().equals(TRAVEL) && e.signal() instanceof Travel travel) {
        x = travel.x();
      }
    }
    m.put(PHASE, phase);
    m.put(X, x);
    return m;
  }
}

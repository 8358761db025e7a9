package org.armgals.examples.robots;

import static org.armgals.examples.robots.CaterpillarSignals.BEAT;
import static org.armgals.examples.robots.CaterpillarSignals.HEARD;
import static org.armgals.examples.robots.CaterpillarSignals.STROKE;
import static org.armgals.examples.robots.CaterpillarSignals.TRAVEL;

import java.util.Map;
import java.util.function.Consumer;
import org.armgals.active.TimeSource;
import org.armgals.examples.robots.CaterpillarModules.Feet;
import org.armgals.examples.robots.CaterpillarModules.Listen;
import org.armgals.examples.robots.CaterpillarModules.Odometer;
import org.armgals.examples.robots.CaterpillarModules.Pacemaker;
import org.armgals.examples.robots.CaterpillarModules.Relay;
import org.armgals.examples.robots.CaterpillarModules.Step;
import org.armgals.examples.robots.CaterpillarSignals.Beat;
import org.armgals.examples.robots.CaterpillarSignals.Travel;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.Adaptation;
import org.armgals.maam.BehaviorModule;
import org.armgals.maam.CycleReport;
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
  private Consumer<Adaptation> onAdapted = change -> {};

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

  /** Tells {@code listener} of each change its meta level made, when it is applied. */
  void onAdapted(Consumer<Adaptation> listener) {
    this.onAdapted = listener;
  }

  @Override
  protected void adapted(Adaptation change) {
    onAdapted.accept(change);
  }

  /**
   * The catalog a meta level of another runtime asks from: the {@code pacemaker} with a {@code
   * stride} (radians) from a {@code phase}, a copy of the one the segment was built with.
   */
  @Override
  protected BehaviorModule module(String name, Map<String, Object> parameters) {
    if (name.equals(PACEMAKER)
        && parameters.get(STRIDE) instanceof Number stride
        && parameters.get(PHASE) instanceof Number phase) {
      return pacemaker.withStride(stride.doubleValue(), phase.doubleValue());
    }
    return super.module(name, parameters);
  }

  /** The pacemaker's stride in a catalog request, radians. */
  static final String STRIDE = "stride";

  /** What a segment shows its meta level: the robot's own, its beat's phase, its travel. */
  @Override
  protected Map<String, Object> observe() {
    Map<String, Object> m = super.observe();
    double phase = -1;
    double x = 0;
    for (CycleReport.Emission e : emissions()) {
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

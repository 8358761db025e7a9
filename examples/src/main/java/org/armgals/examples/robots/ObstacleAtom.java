package org.armgals.examples.robots;

import static org.armgals.examples.robots.ObstacleModules.POSITION;
import static org.armgals.examples.robots.ObstacleModules.STEP_AHEAD;
import static org.armgals.examples.robots.ObstacleModules.STRIDE;
import static org.armgals.examples.robots.ObstacleModules.TICK;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import org.armgals.active.TimeSource;
import org.armgals.examples.robots.ObstacleModules.Carry;
import org.armgals.examples.robots.ObstacleModules.Climb;
import org.armgals.examples.robots.ObstacleModules.Cruise;
import org.armgals.examples.robots.ObstacleModules.Feel;
import org.armgals.examples.robots.ObstacleModules.Feeler;
import org.armgals.examples.robots.ObstacleModules.Feet;
import org.armgals.examples.robots.ObstacleModules.Metronome;
import org.armgals.examples.robots.ObstacleModules.Odometry;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.StructuralMeta;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.Derivator;
import org.armgals.maam.Emission;
import org.armgals.maam.PortRef;
import org.armgals.maam.RobotKind;
import org.armgals.maam.Schema;
import org.armgals.maam.Suppressor;
import org.armgals.maam.spi.Body;
import org.armgals.representation.p.PState;

/**
 * The robot of one atom of {@link ObstacleRobot}'s chain. Every atom runs {@value #CRUISE}; the
 * front atom also runs the {@value #CLIMB} reflex, whose careful stride suppresses cruise's while
 * its feeler sees the step. The meta level may add {@value #LIFT_FRONT} and its connectors from the
 * atoms' kind ({@link #kind}).
 *
 * <pre>{@code
 * cruise:     metronome --tick--> cruise --stride--(S)--> feet      odometry --position-->
 * climb:      feel --step-ahead--> climb --stride--S(cruise.stride, 0.3 s)     feeler
 *             metronome.tick ==D==> climb.tick
 * lift-front: odometry.position ==D==> carry <==D== metronome.tick
 *             carry --stride--S(cruise.stride, 0 s)     (added by the meta level)
 * }</pre>
 */
final class ObstacleAtom extends AbstractRobot {
  static final String CRUISE = "cruise";
  static final String CLIMB = "climb";
  static final String LIFT_FRONT = "lift-front";

  /** How long the climb reflex's stride stays after the feeler last saw the step. */
  static final Duration CLIMB_HOLD = Duration.ofMillis(300);

  private final int index;
  private final long periodNanos;
  private final Metronome metronome = new Metronome();
  private final Odometry odometry = new Odometry("odometry");
  private final Cruise cruise;

  /**
   * @param index the atom's place in the chain, 0 at the rear; the last one is the front
   */
  ObstacleAtom(int index, Body body, TimeSource time, long periodNanos) {
    super("atom-" + index, body, time);
    this.index = index;
    this.periodNanos = periodNanos;
    this.cruise = new Cruise("cruise", periodNanos, offset(index));
    Feet feet = new Feet("feet", ObstacleGait.FOOT_SLEW);
    addSchema(
        Schema.builder(CRUISE)
            .add(metronome)
            .add(odometry)
            .add(cruise)
            .add(feet)
            .wire(metronome, TICK, cruise, TICK)
            .wire(cruise, STRIDE, feet, STRIDE)
            .build());
    if (index == ObstacleGait.ATOMS - 1) {
      Feel feel = new Feel("feel");
      Climb climb = new Climb("climb", periodNanos, offset(index));
      addSchema(
          Schema.builder(CLIMB)
              .add(feel)
              .add(climb)
              .add(new Feeler("feeler"))
              .wire(feel, STEP_AHEAD, climb, STEP_AHEAD)
              .build());
      addConnector(new Derivator(PortRef.of(metronome, TICK), PortRef.of(climb, TICK)));
      // Climbing subsumes cruising: while the feeler sees the step, and a little after.
      addConnector(
          new Suppressor(PortRef.of(climb, STRIDE), PortRef.of(cruise, STRIDE), CLIMB_HOLD));
    }
  }

  /** Neighbouring atoms are half a gait period apart: three feet down, three up. */
  private static double offset(int index) {
    return index % 2 == 0 ? 0 : Math.PI;
  }

  /** The observed position of the atom along the path, metres (its odometry's). */
  static final String X = "x";

  /** The edge of the step in a request for {@value #LIFT_FRONT}, metres along the path. */
  static final String EDGE = "edge";

  /** The connectors that join {@value #LIFT_FRONT} to the atom's program, by catalog name. */
  static final List<String> LIFT_FRONT_CONNECTORS =
      List.of("lift-front-position", "lift-front-tick", "lift-front-suppresses-cruise");

  /**
   * The kind of the chain's atoms, {@code ObstacleAtom}: they observe their position; its catalog
   * has the {@value #LIFT_FRONT} schema for a step whose {@value #EDGE} is given, and the three
   * connectors that feed it and let it suppress cruise's stride ({@link #LIFT_FRONT_CONNECTORS}).
   */
  static StructuralMeta<PState> kind(Kernel kernel) {
    return RobotKind.builder("ObstacleAtom", ObstacleAtom.class)
        .observing(Map.of(X, 0.0))
        .schema(
            LIFT_FRONT,
            (atom, p) ->
                Schema.builder(LIFT_FRONT)
                    .add(new Carry("carry", atom.index, p.number(EDGE), atom.periodNanos))
                    .build())
        .connector(
            LIFT_FRONT_CONNECTORS.get(0),
            (atom, p) ->
                new Derivator(PortRef.of(atom.odometry, POSITION), new PortRef("carry", POSITION)))
        .connector(
            LIFT_FRONT_CONNECTORS.get(1),
            (atom, p) ->
                new Derivator(PortRef.of(atom.metronome, TICK), new PortRef("carry", TICK)))
        .connector(
            LIFT_FRONT_CONNECTORS.get(2),
            (atom, p) ->
                new Suppressor(
                    new PortRef("carry", STRIDE), PortRef.of(atom.cruise, STRIDE), Duration.ZERO))
        .define(kernel);
  }

  /** What an atom shows its meta level: the robot's own, and where its odometry puts it. */
  @Override
  protected Map<String, Object> observe() {
    Map<String, Object> m = super.observe();
    double x = 0;
    for (Emission e : emissions()) {
      if (e.signal() instanceof ObstacleSignals.Position p) {
        x = p.x();
      }
    }
    m.put(X, x);
    return m;
  }
}

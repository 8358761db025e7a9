package org.armgals.examples.robots;

import static org.armgals.examples.robots.ObstacleModules.POSITION;
import static org.armgals.examples.robots.ObstacleModules.STEP_AHEAD;
import static org.armgals.examples.robots.ObstacleModules.STRIDE;
import static org.armgals.examples.robots.ObstacleModules.TICK;

import java.time.Duration;
import java.util.List;
import org.armgals.active.TimeSource;
import org.armgals.examples.robots.ObstacleModules.Carry;
import org.armgals.examples.robots.ObstacleModules.Climb;
import org.armgals.examples.robots.ObstacleModules.Cruise;
import org.armgals.examples.robots.ObstacleModules.Feel;
import org.armgals.examples.robots.ObstacleModules.Feeler;
import org.armgals.examples.robots.ObstacleModules.Feet;
import org.armgals.examples.robots.ObstacleModules.Metronome;
import org.armgals.examples.robots.ObstacleModules.Odometry;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.Adaptation;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.Derivator;
import org.armgals.maam.PortRef;
import org.armgals.maam.Schema;
import org.armgals.maam.Suppressor;
import org.armgals.maam.spi.Body;

/**
 * The robot of one atom of {@link ObstacleRobot}'s chain. Every atom runs {@value #CRUISE}; the
 * front atom also runs the {@value #CLIMB} reflex, whose careful stride suppresses cruise's while
 * its feeler sees the step. The meta level may add {@value #LIFT_FRONT} ({@link #liftFront}).
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
   * @param behavioralMeta its meta level, or null for none
   */
  ObstacleAtom(int index, Body body, TimeSource time, long periodNanos, BMetaRobot behavioralMeta) {
    super("atom-" + index, body, time);
    this.index = index;
    this.periodNanos = periodNanos;
    this.cruise = new Cruise("cruise", periodNanos, offset(index));
    Feet feet = new Feet("feet");
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
    if (behavioralMeta != null) {
      setBehavioralMeta(behavioralMeta);
    }
  }

  /** Neighbouring atoms are half a gait period apart: three feet down, three up. */
  private static double offset(int index) {
    return index % 2 == 0 ? 0 : Math.PI;
  }

  /**
   * The adaptations that add the lift-front schema for a step whose edge is at {@code edge} (m):
   * the schema, the derivators that feed it, and its suppressor of cruise's stride.
   */
  List<Adaptation> liftFront(double edge) {
    Carry carry = new Carry("carry", index, edge, periodNanos);
    return List.of(
        new Adaptation.AddSchema(Schema.builder(LIFT_FRONT).add(carry).build()),
        new Adaptation.AddConnector(
            new Derivator(PortRef.of(odometry, POSITION), PortRef.of(carry, POSITION))),
        new Adaptation.AddConnector(
            new Derivator(PortRef.of(metronome, TICK), PortRef.of(carry, TICK))),
        new Adaptation.AddConnector(
            new Suppressor(PortRef.of(carry, STRIDE), PortRef.of(cruise, STRIDE), Duration.ZERO)));
  }
}

package org.armgals.examples.robots;

import static org.armgals.examples.robots.CaterpillarSignals.BEAT;
import static org.armgals.examples.robots.CaterpillarSignals.HEARD;
import static org.armgals.examples.robots.CaterpillarSignals.STROKE;
import static org.armgals.examples.robots.CaterpillarSignals.TRAVEL;

import java.util.List;
import java.util.Locale;
import org.armgals.examples.robots.CaterpillarSignals.Beat;
import org.armgals.examples.robots.CaterpillarSignals.Heard;
import org.armgals.examples.robots.CaterpillarSignals.Stroke;
import org.armgals.examples.robots.CaterpillarSignals.Travel;
import org.armgals.maam.Actuator;
import org.armgals.maam.Inputs;
import org.armgals.maam.Outputs;
import org.armgals.maam.Perceptor;
import org.armgals.maam.Port;
import org.armgals.maam.Reactor;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegBinding;
import org.armgals.maam.spi.NeighbourMessage;

/**
 * The behavior modules of a caterpillar segment. Every segment runs the same ones; the chain's head
 * (the segment whose front leg is free) beats its own rhythm, the others follow the rhythm their
 * front neighbour sends them.
 */
final class CaterpillarModules {

  private CaterpillarModules() {}

  /** The leg towards the head. */
  static final Leg FRONT = Leg.PX;

  /** The leg towards the tail. */
  static final Leg BACK = Leg.MX;

  /** The legs the segment stands and walks on, a pair slanting down either side of the chain. */
  static final List<Leg> FEET = List.of(Leg.MZ, Leg.MY);

  /** Perceptor: the rhythm message from the segment ahead, if one came in this cycle. */
  record Listen(String name) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(HEARD);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      for (NeighbourMessage m : body.read(Atom.INBOX).messages()) {
        if (m.leg() == FRONT) {
          out.emit(HEARD, decode(m.payload()));
        }
      }
    }
  }

  /** Perceptor: where the segment is on the ground. */
  record Odometer(String name) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(TRAVEL);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      TrackedBody.Place p = body.read(TrackedBody.POSITION);
      out.emit(TRAVEL, new Travel(p.x(), p.y()));
    }
  }

  /**
   * Reactor, the phase generator: follows the rhythm heard from ahead, {@code lag} of a step behind
   * it; beats its own with its own period and stride when it hears none (at the head, or when a
   * message is lost). A new segment eases in: its own stride grows from nothing over its first
   * step, so that the feet, which start straight, do not all jump to their places at once and shake
   * a stiff chain apart. Keeps its phase between cycles: only the robot's thread touches it.
   */
  static final class Pacemaker implements Reactor {
    private final String name;
    private final double periodSeconds;
    private final double stride;
    private final double lag;
    private final double cycleSeconds;
    private double phase;

    /** How much of its stride it beats, growing to 1 over its first step. */
    private double ease;

    /**
     * @param periodSeconds seconds per step when beating its own rhythm
     * @param stride half the leg's swing along the chain, radians, when beating its own rhythm
     * @param lag how far behind the segment ahead, in steps
     * @param cycleSeconds the control period
     * @param phase where to start, in steps
     */
    Pacemaker(
        String name,
        double periodSeconds,
        double stride,
        double lag,
        double cycleSeconds,
        double phase) {
      this(name, periodSeconds, stride, lag, cycleSeconds, phase, 0);
    }

    private Pacemaker(
        String name,
        double periodSeconds,
        double stride,
        double lag,
        double cycleSeconds,
        double phase,
        double ease) {
      this.name = name;
      this.periodSeconds = periodSeconds;
      this.stride = stride;
      this.lag = lag;
      this.cycleSeconds = cycleSeconds;
      this.phase = wrap(phase);
      this.ease = ease;
    }

    /** The same pacemaker with another stride, going on from {@code phase}, at full stride. */
    Pacemaker withStride(double newStride, double fromPhase) {
      return new Pacemaker(name, periodSeconds, newStride, lag, cycleSeconds, fromPhase, 1);
    }

    double stride() {
      return stride;
    }

    @Override
    public String name() {
      return name;
    }

    @Override
    public List<Port<?>> inputs() {
      return List.of(HEARD);
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(BEAT);
    }

    @Override
    public void react(Inputs in, Outputs out) {
      Heard heard = in.get(HEARD);
      if (heard != null) {
        // Sent last cycle: the sender has moved on by one cycle since.
        phase = wrap(heard.phase() + cycleSeconds / heard.period() - lag);
        out.emit(BEAT, new Beat(phase, heard.period(), heard.stride()));
      } else {
        phase = wrap(phase + cycleSeconds / periodSeconds);
        ease = Math.min(1, ease + cycleSeconds / periodSeconds);
        out.emit(BEAT, new Beat(phase, periodSeconds, stride * ease));
      }
    }
  }

  /**
   * Reactor, the stepping pattern: in the first half of a step the feet's tips go straight back
   * along the chain under the kernel, carrying the segment (stance); in the second they come
   * forward round the outer edge of their cones, raised by the tilt (swing).
   */
  record Step(String name) implements Reactor {
    @Override
    public List<Port<?>> inputs() {
      return List.of(BEAT);
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(STROKE);
    }

    @Override
    public void react(Inputs in, Outputs out) {
      Beat beat = in.get(BEAT);
      if (beat == null) {
        return;
      }
      double u = beat.phase();
      double a = beat.stride();
      double duty = CaterpillarTuning.DUTY;
      if (u < duty) {
        double along = a - 2 * a * u / duty;
        out.emit(STROKE, new Stroke(along, StandingChain.level(along)));
      } else {
        double th = Math.PI * (u - duty) / (1 - duty);
        double along = -a * Math.cos(th);
        double lift = Math.sin(th);
        out.emit(STROKE, new Stroke(along, StandingChain.level(along) + a * lift * lift));
      }
    }
  }

  /** Actuator: moves both feet to the stroke. */
  record Feet(String name) implements Actuator {
    @Override
    public List<Port<?>> inputs() {
      return List.of(STROKE);
    }

    @Override
    public void act(Inputs in, Body body) {
      Stroke stroke = in.get(STROKE);
      if (stroke != null) {
        for (Leg foot : FEET) {
          body.command(
              Atom.target(foot), CaterpillarTuning.foot(foot, stroke.along(), stroke.out()));
        }
      }
    }
  }

  /** Actuator: passes the rhythm on to the segment behind, through the back leg if bound. */
  record Relay(String name) implements Actuator {
    @Override
    public List<Port<?>> inputs() {
      return List.of(BEAT);
    }

    @Override
    public void act(Inputs in, Body body) {
      Beat beat = in.get(BEAT);
      if (beat != null && body.read(Atom.binding(BACK)) instanceof LegBinding.Bound) {
        body.command(Atom.SEND, new NeighbourMessage(BACK, encode(beat)));
      }
    }
  }

  static String encode(Beat beat) {
    return beat.phase() + " " + beat.period() + " " + beat.stride();
  }

  static Heard decode(String payload) {
    String[] parts = payload.split(" ");
    if (parts.length != 3) {
      throw new IllegalArgumentException(
          String.format(Locale.ROOT, "rhythm message '%s': expected phase period stride", payload));
    }
    return new Heard(
        Double.parseDouble(parts[0]), Double.parseDouble(parts[1]), Double.parseDouble(parts[2]));
  }

  static double wrap(double phase) {
    return phase - Math.floor(phase);
  }
}

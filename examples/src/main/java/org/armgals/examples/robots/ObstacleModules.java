package org.armgals.examples.robots;

import static org.armgals.examples.robots.ObstacleGait.LIFT_MY;
import static org.armgals.examples.robots.ObstacleGait.LIFT_MZ;
import static org.armgals.examples.robots.ObstacleGait.SWEEP_MY;
import static org.armgals.examples.robots.ObstacleGait.SWEEP_MZ;

import java.util.List;
import org.armgals.examples.robots.ObstacleSignals.Position;
import org.armgals.examples.robots.ObstacleSignals.StepAhead;
import org.armgals.examples.robots.ObstacleSignals.Stride;
import org.armgals.examples.robots.ObstacleSignals.Tick;
import org.armgals.maam.Actuator;
import org.armgals.maam.Inputs;
import org.armgals.maam.Outputs;
import org.armgals.maam.Perceptor;
import org.armgals.maam.Port;
import org.armgals.maam.Reactor;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;

/** The behavior modules of {@link ObstacleRobot}'s atoms, and their ports. */
final class ObstacleModules {
  static final Port<Tick> TICK = Port.of("tick", Tick.class);
  static final Port<Position> POSITION = Port.of("position", Position.class);
  static final Port<StepAhead> STEP_AHEAD = Port.of("step-ahead", StepAhead.class);
  static final Port<Stride> STRIDE = Port.of("stride", Stride.class);

  private ObstacleModules() {}

  /** The gait's phase (rad) at {@code cycle}: every atom counts the same cycles, so they agree. */
  static double phase(long cycle, long periodNanos, double offset) {
    double seconds = cycle * (periodNanos / 1e9);
    return 2 * Math.PI * ObstacleGait.FREQUENCY * seconds + offset;
  }

  /** From 0 to 1 over the first {@link ObstacleGait#RAMP} seconds: a gentle start. */
  static double ramp(long cycle, long periodNanos) {
    return Math.min(1, cycle * (periodNanos / 1e9) / ObstacleGait.RAMP);
  }

  /** Beats once per cycle: the shared time of the gait. */
  static final class Metronome implements Perceptor {
    private long cycle;

    @Override
    public String name() {
      return "metronome";
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(TICK);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      out.emit(TICK, new Tick(cycle++));
    }
  }

  /** Reads where the atom is along the path. */
  record Odometry(String name) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(POSITION);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      out.emit(POSITION, new Position(body.read(TrackedBody.POSITION).x()));
    }
  }

  /** Cruise: the alternating tripod, at full stride once ramped up. */
  record Cruise(String name, long periodNanos, double offset) implements Reactor {
    @Override
    public List<Port<?>> inputs() {
      return List.of(TICK);
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(STRIDE);
    }

    @Override
    public void react(Inputs in, Outputs out) {
      Tick tick = in.get(TICK);
      if (tick != null) {
        double ramp = ramp(tick.cycle(), periodNanos);
        out.emit(
            STRIDE,
            new Stride(
                phase(tick.cycle(), periodNanos, offset),
                ramp * ObstacleGait.SWEEP,
                ramp * ObstacleGait.LIFT,
                false));
      }
    }
  }

  /**
   * Drives the two feet (−z and −y legs) as the stride says, each joint angle moving at most {@code
   * slew} radians per cycle: the gait's own strides are slower than that, but a change of stride
   * (climb taking over, an atom carried or set down, the tripods changing step around it) is eased
   * in rather than thrown at the servos, whose stiff legs would jolt the chain. Keeps its last
   * command between cycles: only the robot's thread touches it.
   */
  static final class Feet implements Actuator {
    private final String name;
    private final double slew;

    /** The last command: −z's two joint angles, then −y's. */
    private final double[] last = new double[4];

    /**
     * @param slew the most a joint angle's command moves in a cycle, radians
     */
    Feet(String name, double slew) {
      this.name = name;
      this.slew = slew;
    }

    @Override
    public String name() {
      return name;
    }

    @Override
    public List<Port<?>> inputs() {
      return List.of(STRIDE);
    }

    @Override
    public void act(Inputs in, Body body) {
      Stride stride = in.get(STRIDE);
      if (stride == null) {
        return;
      }
      double[] next = new double[4];
      if (stride.carried()) {
        double out = ObstacleGait.CARRY;
        next[0] = LIFT_MZ * out;
        next[3] = LIFT_MY * out;
      } else {
        // The −y foot is half a period behind the −z foot: the atom always stands on one of them.
        double pz = stride.phase();
        double py = stride.phase() + Math.PI;
        next[0] = LIFT_MZ * stride.lift() * Math.max(0, -Math.sin(pz));
        next[1] = SWEEP_MZ * stride.sweep() * Math.cos(pz);
        next[2] = SWEEP_MY * stride.sweep() * Math.cos(py);
        next[3] = LIFT_MY * stride.lift() * Math.max(0, -Math.sin(py));
      }
      for (int k = 0; k < last.length; k++) {
        double step = next[k] - last[k];
        last[k] += Math.max(-slew, Math.min(slew, step));
      }
      body.command(Atom.target(Leg.MZ), ObstacleGait.joint(last[0], last[1]));
      body.command(Atom.target(Leg.MY), ObstacleGait.joint(last[2], last[3]));
    }
  }

  /** Holds the front atom's free +x leg pointing down ahead: the feeler. */
  record Feeler(String name) implements Actuator {
    @Override
    public List<Port<?>> inputs() {
      return List.of();
    }

    @Override
    public void act(Inputs in, Body body) {
      body.command(
          Atom.target(Leg.PX), ObstacleGait.joint(ObstacleGait.FEELER_A1, ObstacleGait.FEELER_A2));
    }
  }

  /** Emits a stimulus when the feeler's proximity ray meets something nearer than the ground. */
  record Feel(String name) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(STEP_AHEAD);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      double distance = body.read(Atom.proximity(Leg.PX));
      if (distance < ObstacleGait.NEAR) {
        out.emit(STEP_AHEAD, new StepAhead(distance));
      }
    }
  }

  /** The climb reflex: before a step, a careful stride, shorter and lifting the feet higher. */
  record Climb(String name, long periodNanos, double offset) implements Reactor {
    @Override
    public List<Port<?>> inputs() {
      return List.of(STEP_AHEAD, TICK);
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(STRIDE);
    }

    @Override
    public void react(Inputs in, Outputs out) {
      Tick tick = in.get(TICK);
      if (in.get(STEP_AHEAD) != null && tick != null) {
        out.emit(
            STRIDE,
            new Stride(
                phase(tick.cycle(), periodNanos, offset),
                ObstacleGait.CLIMB_SWEEP,
                ObstacleGait.CLIMB_LIFT,
                false));
      }
    }
  }

  /**
   * Lift-front, the schema the meta level adds: an atom near the step's edge swings its feet up and
   * is carried over by its neighbours; the atoms still standing keep alternating their tripods
   * among themselves, so two neighbouring standing atoms are never in step. Emits nothing when no
   * atom of the chain is carried.
   *
   * @param index the atom's place in the chain, 0 at the rear
   * @param edge where the meta level located the step's edge (m)
   */
  record Carry(String name, int index, double edge, long periodNanos) implements Reactor {
    @Override
    public List<Port<?>> inputs() {
      return List.of(POSITION, TICK);
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(STRIDE);
    }

    @Override
    public void react(Inputs in, Outputs out) {
      Position position = in.get(POSITION);
      Tick tick = in.get(TICK);
      if (position == null || tick == null) {
        return;
      }
      if (carried(position.x())) {
        out.emit(STRIDE, new Stride(0, 0, 0, true));
        return;
      }
      int standingBehind = 0;
      boolean anyCarried = false;
      for (int other = 0; other < ObstacleGait.ATOMS; other++) {
        boolean c = carried(position.x() + (other - index) * ObstacleGait.SPACING);
        anyCarried |= c;
        if (other < index && !c) {
          standingBehind++;
        }
      }
      if (anyCarried) {
        double offset = standingBehind % 2 == 0 ? 0 : Math.PI;
        out.emit(
            STRIDE,
            new Stride(
                phase(tick.cycle(), periodNanos, offset),
                ObstacleGait.SWEEP,
                ObstacleGait.LIFT,
                false));
      }
    }

    private boolean carried(double x) {
      return x > edge - ObstacleGait.CARRY_BEHIND && x < edge + ObstacleGait.CARRY_BEYOND;
    }
  }
}

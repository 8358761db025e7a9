package org.armgals.examples.robots;

import static org.armgals.examples.robots.ReconfigureTuning.advance;

import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.armgals.examples.robots.ObstacleSignals.Stride;
import org.armgals.examples.robots.ReconfigureSignals.Beat;
import org.armgals.examples.robots.ReconfigureSignals.Bonds;
import org.armgals.examples.robots.ReconfigureSignals.Heard;
import org.armgals.examples.robots.ReconfigureSignals.Walls;
import org.armgals.maam.Actuator;
import org.armgals.maam.Inputs;
import org.armgals.maam.Outputs;
import org.armgals.maam.Perceptor;
import org.armgals.maam.Port;
import org.armgals.maam.Reactor;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.BindCommand;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegBinding;
import org.armgals.maam.spi.NeighbourMessage;

/**
 * The behavior modules of {@link Reconfigure}'s atoms, and their ports. A head beats the rhythm
 * ({@link Pacemaker}); a follower takes it from the atom ahead ({@link Listen}, {@link Follow}),
 * half a gait period later; every atom with a neighbour behind passes its beat on ({@link Relay}).
 */
final class ReconfigureModules {
  static final Port<Beat> BEAT = Port.of("beat", Beat.class);
  static final Port<Heard> HEARD = Port.of("heard", Heard.class);
  static final Port<Bonds> BONDS = Port.of("bonds", Bonds.class);
  static final Port<Walls> WALLS = Port.of("walls", Walls.class);
  static final Port<Stride> STRIDE = ObstacleModules.STRIDE;

  /** The leg towards the head, and the leg towards the tail. */
  static final Leg AHEAD = Leg.PX;

  static final Leg BEHIND = Leg.MX;

  private ReconfigureModules() {}

  /**
   * Perceptor of a head: beats the rhythm itself, from {@code phase} (rad) and {@code amplitude},
   * which grows to 1 over {@link ObstacleGait#RAMP} seconds. Keeps its phase: one per robot.
   */
  static final class Pacemaker implements Perceptor {
    private final String name;
    private final double step;
    private final double growth;
    private double phase;
    private double amplitude;

    Pacemaker(String name, long periodNanos, double phase, double amplitude) {
      this.name = name;
      this.step = advance(periodNanos);
      this.growth = periodNanos / 1e9 / ReconfigureTuning.RAMP;
      this.phase = phase;
      this.amplitude = amplitude;
    }

    @Override
    public String name() {
      return name;
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(BEAT);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      out.emit(BEAT, new Beat(phase, amplitude));
      phase = (phase + step) % (2 * Math.PI);
      amplitude = Math.min(1, amplitude + growth);
    }
  }

  /** Perceptor of a follower: the beat that came in through the front bond, if any. */
  record Listen(String name) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(HEARD);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      for (NeighbourMessage m : body.read(Atom.INBOX).messages()) {
        if (m.leg() == AHEAD) {
          String[] parts = m.payload().split(" ");
          out.emit(HEARD, new Heard(Double.parseDouble(parts[0]), Double.parseDouble(parts[1])));
        }
      }
    }
  }

  /**
   * Reactor of a follower: half a gait period behind the atom ahead (neighbours alternate their
   * tripods), counting the cycle the message took; runs on alone when nothing comes in.
   */
  static final class Follow implements Reactor {
    private final String name;
    private final double step;
    private double phase = Math.PI;
    private double amplitude;

    Follow(String name, long periodNanos) {
      this.name = name;
      this.step = advance(periodNanos);
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
        phase = (heard.phase() + step + Math.PI) % (2 * Math.PI);
        amplitude = heard.amplitude();
      } else {
        phase = (phase + step) % (2 * Math.PI);
      }
      out.emit(BEAT, new Beat(phase, amplitude));
    }
  }

  /** Actuator: sends the beat to the atom behind, through the back bond. */
  record Relay(String name) implements Actuator {
    @Override
    public List<Port<?>> inputs() {
      return List.of(BEAT);
    }

    @Override
    public void act(Inputs in, Body body) {
      Beat beat = in.get(BEAT);
      if (beat != null) {
        body.command(
            Atom.SEND,
            new NeighbourMessage(
                BEHIND, String.format(Locale.ROOT, "%s %s", beat.phase(), beat.amplitude())));
      }
    }
  }

  /** Reactor: the beat as a stride of {@link ObstacleRobot}'s alternating-tripod crawl. */
  record Crawl(String name) implements Reactor {
    @Override
    public List<Port<?>> inputs() {
      return List.of(BEAT);
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(STRIDE);
    }

    @Override
    public void react(Inputs in, Outputs out) {
      Beat beat = in.get(BEAT);
      if (beat != null) {
        out.emit(
            STRIDE,
            new Stride(
                beat.phase(),
                beat.amplitude() * ReconfigureTuning.SWEEP,
                beat.amplitude() * ReconfigureTuning.LIFT,
                false));
      }
    }
  }

  /** Perceptor: what the two chain legs are bound to, every cycle. */
  record Chain(String name) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(BONDS);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      out.emit(BONDS, new Bonds(neighbour(body, AHEAD), neighbour(body, BEHIND)));
    }

    private static Optional<String> neighbour(Body body, Leg leg) {
      return body.read(Atom.binding(leg)) instanceof LegBinding.Bound b
          ? Optional.of(b.neighbour())
          : Optional.empty();
    }
  }

  /**
   * Perceptor of the front atom: emits when both side legs (+y and +z, which point 45° up across
   * the path on an atom turned 45° about x) see a wall nearer than {@link
   * ReconfigureTuning#WALL_NEAR}.
   */
  record Survey(String name) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(WALLS);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      double left = body.read(Atom.proximity(Leg.PY));
      double right = body.read(Atom.proximity(Leg.PZ));
      if (left < ReconfigureTuning.WALL_NEAR && right < ReconfigureTuning.WALL_NEAR) {
        out.emit(WALLS, new Walls(left, right));
      }
    }
  }

  /** Actuator the meta level adds for the split: releases the bond on {@code leg}. */
  record Detach(String name, Leg leg) implements Actuator {
    @Override
    public List<Port<?>> inputs() {
      return List.of();
    }

    @Override
    public void act(Inputs in, Body body) {
      body.command(Atom.bind(leg), BindCommand.UNBIND);
    }
  }
}

package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.function.Consumer;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.Actuator;
import org.armgals.maam.Inputs;
import org.armgals.maam.Outputs;
import org.armgals.maam.Perceptor;
import org.armgals.maam.Port;
import org.armgals.maam.Reactor;
import org.armgals.maam.Schema;
import org.armgals.maam.Signal;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;

/**
 * The robot of one atom of {@link Distributed}'s chain, in the atom's own runtime: one schema,
 * {@code crawl}, where {@code clock} (a perceptor of the world's time) feeds {@code gait} (a
 * reactor placing the atom in the chain's wave, {@link DistributedGait}), which feeds {@code legs}
 * (an actuator driving the two lower legs). The phase comes from the world's time in the readings,
 * not from the robot's own clock: the robot answers each reading with the same commands however
 * late it comes, so the world's run does not depend on when the atom's island ticks. Its {@code
 * receive} schema feeds the body the readings the world sent its entity; its {@code report} schema
 * sends the world the commands of each cycle.
 */
final class DistributedCrawler extends AbstractRobot {
  static final Port<Phase> PHASE = Port.of("phase", Phase.class);
  static final Port<Stride> STRIDE = Port.of("stride", Stride.class);

  /** Where the atom is in its stroke, in [0, 1). */
  record Phase(double value) implements Signal {}

  /** Where the two lower legs should point. */
  record Stride(LegAngles minusZ, LegAngles minusY) implements Signal {}

  private final DistributedRemoteBody remote;
  private final Consumer<Object> toWorld;

  /**
   * @param toWorld where the robot's messages to the world go (its commands), on the robot's thread
   */
  DistributedCrawler(DistributedRemoteBody body, int index, int count, Consumer<Object> toWorld) {
    super(
        "crawler-" + body.id(),
        body,
        () -> Math.max(0, body.read(DistributedRemoteBody.WORLD_TIME)));
    this.remote = body;
    this.toWorld = requireNonNull(toWorld, "toWorld");
    WorldClock clock = new WorldClock("clock", index, count);
    Gait gait = new Gait("gait");
    LegDrive legs = new LegDrive("legs");
    addSchema(Schema.builder("receive").add(new Inlink()).build());
    addSchema(
        Schema.builder("crawl")
            .add(clock)
            .add(gait)
            .add(legs)
            .wire(clock, PHASE, gait, PHASE)
            .wire(gait, STRIDE, legs, STRIDE)
            .build());
    addSchema(Schema.builder("report").add(new Outlink()).build());
  }

  /**
   * Feeds the body the readings the world sent the robot's entity, taken at this release: the first
   * module of each cycle.
   */
  private final class Inlink implements Perceptor {
    @Override
    public String name() {
      return "inlink";
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of();
    }

    @Override
    public void perceive(Body body, Outputs out) {
      for (Object input : received()) {
        if (input instanceof DistributedWire.Readings readings) {
          remote.feed(readings);
        }
      }
    }
  }

  /** Sends the world the commands of this cycle, if they answer new readings: the last module. */
  private final class Outlink implements Actuator {
    @Override
    public String name() {
      return "outlink";
    }

    @Override
    public List<Port<?>> inputs() {
      return List.of();
    }

    @Override
    public void act(Inputs in, Body body) {
      DistributedWire.Commands commands = remote.takeCommands();
      if (commands != null) {
        toWorld.accept(commands);
      }
    }
  }

  /** The atom's phase from the world's time; nothing before the first readings. */
  record WorldClock(String name, int index, int count) implements Perceptor {
    @Override
    public List<Port<?>> outputs() {
      return List.of(PHASE);
    }

    @Override
    public void perceive(Body body, Outputs out) {
      long nanos = body.read(DistributedRemoteBody.WORLD_TIME);
      if (nanos >= 0) {
        out.emit(PHASE, new Phase(DistributedGait.phase(nanos / 1e9, index, count)));
      }
    }
  }

  /** The two lower legs row in opposite phase. */
  record Gait(String name) implements Reactor {
    @Override
    public List<Port<?>> inputs() {
      return List.of(PHASE);
    }

    @Override
    public List<Port<?>> outputs() {
      return List.of(STRIDE);
    }

    @Override
    public void react(Inputs in, Outputs out) {
      Phase phase = in.get(PHASE);
      if (phase != null) {
        double other = (phase.value() + 0.5) % 1.0;
        out.emit(
            STRIDE,
            new Stride(
                DistributedGait.leg(phase.value(), DistributedGait.FRONT_MZ),
                DistributedGait.leg(other, DistributedGait.FRONT_MY)));
      }
    }
  }

  /** Sends the stride to the legs. */
  record LegDrive(String name) implements Actuator {
    @Override
    public List<Port<?>> inputs() {
      return List.of(STRIDE);
    }

    @Override
    public void act(Inputs in, Body body) {
      Stride stride = in.get(STRIDE);
      if (stride != null) {
        body.command(Atom.target(Leg.MZ), stride.minusZ());
        body.command(Atom.target(Leg.MY), stride.minusY());
      }
    }
  }
}

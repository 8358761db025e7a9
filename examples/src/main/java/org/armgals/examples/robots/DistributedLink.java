package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import org.armgals.active.Address;
import org.armgals.gals.CycleContext;
import org.armgals.gals.Reaction;
import org.armgals.maam.AbstractRobot;

/**
 * The second reaction of an atom's robot entity in {@link DistributedAtomMain}, run after the
 * robot's cycle in each release: what crosses between the atom's island and the world.
 */
final class DistributedLink implements Reaction<AbstractRobot> {
  private final Address world;
  private final DistributedRemoteBody body;
  private final DistributedWire.Joined joined;
  private boolean told;

  DistributedLink(Address world, DistributedRemoteBody body, DistributedWire.Joined joined) {
    this.world = requireNonNull(world, "world");
    this.body = requireNonNull(body, "body");
    this.joined = requireNonNull(joined, "joined");
  }

  @Override
  public void react(CycleContext<AbstractRobot> cycle) {
    if (!told) {
      cycle.emit(world, joined);
      told = true;
    }
    DistributedWire.Commands commands = body.takeCommands();
    if (commands != null) {
      cycle.emit(world, commands);
    }
    for (Object input : cycle.inputs()) {
      if (input instanceof DistributedWire.Readings readings) {
        body.feed(readings);
      }
    }
  }
}

package org.armgals.maam;

import java.util.List;

/**
 * A module of reflex behavior (paper §5.1): a {@link Perceptor} turns sensor readings into stimuli,
 * a {@link Reactor} turns stimuli into reaction parameters, an {@link Actuator} turns reaction
 * parameters into commands to the body. The robot runs each module once per cycle, in the order of
 * its {@link Schedule}, on the robot's thread; a module may keep state in its fields between cycles
 * (no other thread touches it).
 *
 * <p>Its name is unique in a robot; its ports are fixed for its lifetime (the schedule and the
 * wiring are computed from them).
 */
public sealed interface BehaviorModule permits Perceptor, Reactor, Actuator {

  /** Its name, unique in a robot: schedules, wires, connectors and errors use it. */
  String name();

  /** Its input ports; none for a perceptor. */
  List<Port<?>> inputs();

  /** Its output ports; none for an actuator. */
  List<Port<?>> outputs();
}

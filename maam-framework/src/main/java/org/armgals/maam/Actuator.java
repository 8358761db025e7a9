package org.armgals.maam;

import java.util.List;
import org.armgals.maam.spi.Body;

/** Turns reaction parameters into commands to the body's actuators (paper §5.1). */
public non-sealed interface Actuator extends BehaviorModule {

  /** An actuator has no output. */
  @Override
  default List<Port<?>> outputs() {
    return List.of();
  }

  /**
   * One step: read {@code in}, command {@code body}.
   *
   * @throws Exception reported to the robot's error handler; the cycle goes on
   */
  void act(Inputs in, Body body) throws Exception;
}

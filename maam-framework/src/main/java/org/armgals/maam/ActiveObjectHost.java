package org.armgals.maam;

import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Clock;
import org.armgals.active.ObjectConfig;
import org.armgals.active.ReactiveCycle;

/**
 * Runs a robot as a synchronous active object of arm-active: its cycle is the object's {@link
 * ReactiveCycle}, released by the clock. The one class that knows how a robot is hosted: when
 * arm-gals' reactive entities land, a robot becomes one of those here, and nowhere else.
 */
final class ActiveObjectHost {

  private ActiveObjectHost() {}

  static ActiveObject<ReactiveCycle> start(
      AbstractRobot robot, ActiveRuntime runtime, Clock clock) {
    ReactiveCycle cycle = instant -> robot.cycle();
    return runtime.spawn(cycle, ObjectConfig.synchronous(clock));
  }
}

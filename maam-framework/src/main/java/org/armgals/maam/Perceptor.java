package org.armgals.maam;

import java.util.List;
import org.armgals.maam.spi.Body;

/** Reads sensors and emits stimuli, or nothing when the stimulus is absent (paper §5.1). */
public non-sealed interface Perceptor extends BehaviorModule {

  /** A perceptor has no input. */
  @Override
  default List<Port<?>> inputs() {
    return List.of();
  }

  /**
   * One step: read {@code body}'s sensors, emit on {@code out}.
   *
   * @throws Exception reported to the robot's error handler; the module's emissions of this cycle
   *     are discarded and the cycle goes on
   */
  void perceive(Body body, Outputs out) throws Exception;
}

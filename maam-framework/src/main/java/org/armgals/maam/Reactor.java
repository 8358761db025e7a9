package org.armgals.maam;

/** Computes reaction parameters from stimuli (paper §5.1). */
public non-sealed interface Reactor extends BehaviorModule {

  /**
   * One step: read {@code in}, emit on {@code out}.
   *
   * @throws Exception reported to the robot's error handler; the module's emissions of this cycle
   *     are discarded and the cycle goes on
   */
  void react(Inputs in, Outputs out) throws Exception;
}

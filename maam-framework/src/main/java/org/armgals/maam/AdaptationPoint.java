package org.armgals.maam;

/**
 * Where in its cycle a robot applies the adaptations requested of it (paper §5.4): both points are
 * renewal states, where no module is half-way through its step.
 */
public enum AdaptationPoint {
  /**
   * Before the first module: the cycle runs the adapted program at once (adaptation first, at the
   * risk of the cycle's deadline).
   */
  BEGIN_OF_CYCLE,
  /**
   * After the last module and the behavioral meta's notification: the cycle's reaction is done
   * before adapting (deadline first); the next cycle runs the adapted program.
   */
  END_OF_CYCLE
}

package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.function.BiFunction;
import java.util.function.Consumer;
import java.util.function.Function;

/**
 * The behavioral meta level of a robot (paper §5.4, class {@code BMetaRobot}): notified at the end
 * of every cycle, it integrates the {@link CycleReport} into its model of the robot and may request
 * {@link Adaptation}s, which the robot applies at its {@link org.armgals.kernel.AdaptationPoint}.
 *
 * <p>Threading: called on the robot's thread, after the cycle's modules, once per cycle; its time
 * counts in the cycle's. It may keep its model in fields.
 */
@FunctionalInterface
public interface BMetaRobot {

  /**
   * One notification.
   *
   * @param report what the robot did this cycle
   * @param requests where to send adaptation requests; valid during this call
   * @throws Exception reported to the robot's error handler; the robot goes on
   */
  void onCycle(CycleReport report, Consumer<Adaptation> requests) throws Exception;

  /**
   * The paper's protocol as functions: {@code integrate} folds each report into the model, then
   * {@code decide} turns the model into requests (none, usually).
   */
  static <M> Modelled<M> modelled(
      M initial,
      BiFunction<? super M, CycleReport, ? extends M> integrate,
      Function<? super M, List<Adaptation>> decide) {
    requireNonNull(initial, "initial");
    requireNonNull(integrate, "integrate");
    requireNonNull(decide, "decide");
    return new ModelledBMetaRobot<>(initial, integrate, decide);
  }

  /**
   * A behavioral meta that keeps a model of type {@code M}.
   *
   * @param <M> the model
   */
  sealed interface Modelled<M> extends BMetaRobot permits ModelledBMetaRobot {

    /** The model after the last notification. */
    M model();
  }
}

package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import org.armgals.active.Mode;
import org.armgals.active.ObjectConfig;
import org.armgals.kernel.spi.ReactiveProgram;
import org.jspecify.annotations.Nullable;

/**
 * How an entity is made: the configuration of its active object (mode, clock, buffer), what it
 * notifies at first, when it applies adaptation requests, and, for a reactive entity, its program
 * and how it keeps in step with its behavioral meta. The kernel adds its own listener to the
 * object's, to notify failures to the behavioral meta.
 *
 * <p><b>Lock step.</b> A reactive entity with a lock-step latency {@code k >= 1} makes its meta's
 * pace part of its own, so that a run on a manual clock is reproducible: at the end of each instant
 * {@code n} it sends its meta a barrier after the instant's notifications; the meta answers it once
 * it has handled them, with the adaptation requests it decided on them (it holds them back instead
 * of sending them as events). At its adaptation point of instant {@code n + k} the entity waits for
 * that answer and applies those requests, and only those: the same inputs give the same adaptations
 * at the same instants, whatever the threads and wherever the meta runs. If the answer does not
 * come within {@code lockStepTimeout}, the entity stops waiting for its meta (it runs free from
 * then on, as a reactive level must go on without its deliberative one) and reports the failure.
 * With {@code lockStep == 0} (free) the entity never waits: a request is applied at the first
 * adaptation point after it arrives.
 *
 * @param config the active object's configuration
 * @param notification what it notifies its behavioral meta of at first
 * @param adaptationPoint when it applies adaptation requests; other than {@link
 *     AdaptationPoint#ON_ARRIVAL} only for a synchronous object
 * @param program what a reactive entity does at each release; {@code null}: it dispatches the
 *     stimuli it takes to its activation
 * @param lockStep the meta's latency in instants, {@code >= 1}, or 0 for free running; above 0 only
 *     for a synchronous object adapting at the beginning or the end of a cycle
 * @param lockStepTimeout how long an adaptation point waits for the meta in lock step; positive
 */
public record EntityOptions(
    ObjectConfig config,
    NotificationPolicy notification,
    AdaptationPoint adaptationPoint,
    @Nullable ReactiveProgram program,
    int lockStep,
    Duration lockStepTimeout) {

  /** How long a lock-step entity waits for its meta by default. */
  public static final Duration DEFAULT_LOCK_STEP_TIMEOUT = Duration.ofSeconds(10);

  /** Checks the options as a whole. */
  public EntityOptions {
    requireNonNull(config, "config");
    requireNonNull(notification, "notification");
    requireNonNull(adaptationPoint, "adaptationPoint");
    requireNonNull(lockStepTimeout, "lockStepTimeout");
    boolean synchronous = config.mode() == Mode.SYNCHRONOUS;
    if (adaptationPoint != AdaptationPoint.ON_ARRIVAL && !synchronous) {
      throw new IllegalArgumentException(
          "adaptation point "
              + adaptationPoint
              + " needs a SYNCHRONOUS object, was "
              + config.mode()
              + "; expected ON_ARRIVAL");
    }
    if (program != null && !synchronous) {
      throw new IllegalArgumentException(
          "a program runs at the releases of a SYNCHRONOUS object, was " + config.mode());
    }
    if (lockStep < 0) {
      throw new IllegalArgumentException(
          "lock-step latency must be >= 0 (0: free), was " + lockStep);
    }
    if (lockStep > 0 && adaptationPoint == AdaptationPoint.ON_ARRIVAL) {
      throw new IllegalArgumentException(
          "lock step "
              + lockStep
              + " needs a SYNCHRONOUS object adapting at BEGIN_OF_CYCLE or END_OF_CYCLE, was "
              + config.mode()
              + " adapting "
              + adaptationPoint);
    }
    if (lockStepTimeout.isNegative() || lockStepTimeout.isZero()) {
      throw new IllegalArgumentException(
          "lock-step timeout must be positive, was " + lockStepTimeout);
    }
  }

  /** Options without a program, running free. */
  public EntityOptions(
      ObjectConfig config, NotificationPolicy notification, AdaptationPoint adaptationPoint) {
    this(config, notification, adaptationPoint, null, 0, DEFAULT_LOCK_STEP_TIMEOUT);
  }

  /** An asynchronous object, notifying complete states and all actions, adapting on arrival. */
  public static EntityOptions defaults() {
    return new EntityOptions(
        ObjectConfig.asynchronous(), NotificationPolicy.all(), AdaptationPoint.ON_ARRIVAL);
  }

  /** These options with another notification policy. */
  public EntityOptions withNotification(NotificationPolicy policy) {
    return new EntityOptions(config, policy, adaptationPoint, program, lockStep, lockStepTimeout);
  }

  /** These options with another object configuration. */
  public EntityOptions withConfig(ObjectConfig objectConfig) {
    return new EntityOptions(
        objectConfig, notification, adaptationPoint, program, lockStep, lockStepTimeout);
  }

  /** These options with another adaptation point. */
  public EntityOptions withAdaptationPoint(AdaptationPoint point) {
    return new EntityOptions(config, notification, point, program, lockStep, lockStepTimeout);
  }

  /** These options with {@code reactiveProgram} run at each release. */
  public EntityOptions withProgram(ReactiveProgram reactiveProgram) {
    requireNonNull(reactiveProgram, "reactiveProgram");
    return new EntityOptions(
        config, notification, adaptationPoint, reactiveProgram, lockStep, lockStepTimeout);
  }

  /** These options in lock step with the meta, {@code latency} instants behind (0: free). */
  public EntityOptions withLockStep(int latency, Duration timeout) {
    return new EntityOptions(config, notification, adaptationPoint, program, latency, timeout);
  }
}

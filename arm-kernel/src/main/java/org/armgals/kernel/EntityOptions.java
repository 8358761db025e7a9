package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import org.armgals.active.Mode;
import org.armgals.active.ObjectConfig;

/**
 * How an entity is made: the configuration of its active object (mode, clock, buffer), what it
 * notifies at first, and when it applies adaptation requests. The kernel adds its own listener to
 * the object's, to notify failures to the behavioral meta.
 *
 * @param config the active object's configuration
 * @param notification what it notifies its behavioral meta of at first
 * @param adaptationPoint when it applies adaptation requests; other than {@link
 *     AdaptationPoint#ON_ARRIVAL} only for a synchronous object
 */
public record EntityOptions(
    ObjectConfig config, NotificationPolicy notification, AdaptationPoint adaptationPoint) {

  /** Checks the options as a whole. */
  public EntityOptions {
    requireNonNull(config, "config");
    requireNonNull(notification, "notification");
    requireNonNull(adaptationPoint, "adaptationPoint");
    if (adaptationPoint != AdaptationPoint.ON_ARRIVAL && config.mode() != Mode.SYNCHRONOUS) {
      throw new IllegalArgumentException(
          "adaptation point "
              + adaptationPoint
              + " needs a SYNCHRONOUS object, was "
              + config.mode()
              + "; expected ON_ARRIVAL");
    }
  }

  /** An asynchronous object, notifying complete states and all actions, adapting on arrival. */
  public static EntityOptions defaults() {
    return new EntityOptions(
        ObjectConfig.asynchronous(), NotificationPolicy.all(), AdaptationPoint.ON_ARRIVAL);
  }

  /** These options with another notification policy. */
  public EntityOptions withNotification(NotificationPolicy policy) {
    return new EntityOptions(config, policy, adaptationPoint);
  }

  /** These options with another object configuration. */
  public EntityOptions withConfig(ObjectConfig objectConfig) {
    return new EntityOptions(objectConfig, notification, adaptationPoint);
  }

  /** These options with another adaptation point. */
  public EntityOptions withAdaptationPoint(AdaptationPoint point) {
    return new EntityOptions(config, notification, point);
  }
}

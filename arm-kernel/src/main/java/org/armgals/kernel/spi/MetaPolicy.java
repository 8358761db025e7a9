package org.armgals.kernel.spi;

import org.armgals.active.Address;
import org.armgals.kernel.Notification;

/**
 * What a behavioral meta-entity does with the notifications of its base entities that pass their
 * filters: reason on its models and adapt (paper §2.3: "the model is defined by necessity").
 *
 * <p>Threading: called on the meta-entity's own object, one notification at a time, after the
 * notification has been integrated in the model; must not block.
 */
@FunctionalInterface
public interface MetaPolicy {

  /** A policy that only keeps models. */
  MetaPolicy MODEL_ONLY = (context, notification) -> {};

  /** {@code notification} passed its entity's filter. */
  void onNotification(MetaContext context, Notification notification) throws Exception;

  /**
   * In lock step ({@link org.armgals.kernel.EntityOptions#withLockStep}): {@code entity} has sent
   * every notification of its instant {@code instant}, all handled. Requests asked for here go with
   * the answer to that instant's barrier, as those asked for on its notifications: they are applied
   * at the entity's adaptation point of instant {@code instant + k}. A policy that decides once per
   * instant, whatever the filter let through, decides here. Does nothing by default.
   */
  default void onInstant(MetaContext context, Address entity, long instant) throws Exception {}
}

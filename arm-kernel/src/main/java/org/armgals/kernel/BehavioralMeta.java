package org.armgals.kernel;

import java.util.List;
import java.util.OptionalLong;
import org.armgals.active.Future;
import org.armgals.active.FutureValue;

/**
 * A behavioral meta-entity (paper §3.1, §4.2): it receives the notifications of its base-level
 * entities, keeps a model of each (an {@link org.armgals.representation.Activation} in the space of
 * the entity's structural meta, built from state events by replacement and from action events by
 * replay), hands what passes each entity's filter to its {@link org.armgals.kernel.spi.MetaPolicy},
 * and adapts its base entities by versioned, acknowledged, damped requests.
 *
 * <p>Every method is a request to the meta-entity's own object, so it is ordered with the
 * notifications that object processes. Threading: any thread.
 */
public interface BehavioralMeta extends Entity {

  /**
   * Becomes the behavioral meta of {@code entity} (taking it from its previous one). The future
   * completes once this meta has made the model and sent the entity its attachment; the entity
   * switches when it processes the attachment, before any event sent to it after the future
   * completed, and answers with a complete state event, from which the model starts.
   */
  Future addBaseLevelEntity(Entity entity);

  /** Stops being the behavioral meta of {@code entity} and drops its model. */
  Future deleteBaseLevelEntity(Entity entity);

  /** The entities it is the behavioral meta of now. */
  List<Entity> baseLevelEntities();

  /**
   * Replaces the filter of {@code entity}'s notifications, a JMS message selector over {@link
   * Notification#properties()} (for example {@code "kind = 'state' AND battery < 0.3"}). The swap
   * is an event of this meta-entity: every notification is judged by exactly one filter, the one in
   * place when the meta takes it. A blank selector accepts everything (the default).
   *
   * @throws IllegalArgumentException the selector does not parse (the message quotes it)
   */
  Future setFilter(Entity entity, String selector);

  /** A snapshot of its model of {@code entity}; fails if it is not one of its base entities. */
  FutureValue<ModelView> model(Entity entity);

  /**
   * Sends {@code entity} an adaptation request, unless the {@link Damping} forbids it now.
   *
   * @return the version of the request sent, or empty if the damping held it back
   */
  FutureValue<OptionalLong> adapt(Entity entity, Adaptation adaptation);
}

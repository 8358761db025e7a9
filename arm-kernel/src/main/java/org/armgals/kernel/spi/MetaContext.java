package org.armgals.kernel.spi;

import java.util.OptionalLong;
import org.armgals.active.Address;
import org.armgals.kernel.Adaptation;
import org.armgals.kernel.BehavioralMeta;
import org.armgals.kernel.Entity;
import org.armgals.kernel.ModelView;

/**
 * What a {@link MetaPolicy} may do, from inside its meta-entity. Valid only during the call it was
 * given to, on the meta-entity's object.
 */
public interface MetaContext {

  /** The behavioral meta-entity running the policy. */
  BehavioralMeta self();

  /** The base entity at {@code entity}. */
  Entity entity(Address entity);

  /** The model of {@code entity} now. */
  ModelView model(Address entity);

  /**
   * Sends an adaptation request to {@code entity} unless the damping forbids it now (flow 3).
   *
   * @return the request's version, or empty if it was held back
   */
  OptionalLong adapt(Address entity, Adaptation adaptation);

  /** Replaces the filter of {@code entity}'s notifications, from the next notification on. */
  void setFilter(Address entity, String selector);

  /**
   * Now, in nanoseconds: while the policy handles a notification (or, in lock step, the end of an
   * instant), the base entity's time then ({@link org.armgals.kernel.Notification#nanoTime()}, the
   * base level's clock, which the damping of what it decides uses too); otherwise the kernel's time
   * source. A meta in another runtime thus decides in the base level's time.
   */
  long nanoTime();
}

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

  /** Time now, from the kernel's time source, in nanoseconds. */
  long nanoTime();
}

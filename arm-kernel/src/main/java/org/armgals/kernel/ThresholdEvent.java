package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.LinkedHashMap;
import java.util.Map;
import org.armgals.active.Address;

/**
 * A meta-event (paper §2.3): a watched value crossed a {@link Threshold}. Sent whatever the rest of
 * the entity's notification policy says, so that a meta that ignores a value can still learn when
 * it starts to matter.
 *
 * @param entity the entity
 * @param destination its behavioral meta
 * @param seq its number in the entity's sequence
 * @param nanoTime the entity's time at the step it tells of, from its kernel's time source (the
 *     base level's clock: virtual time in a simulation, wherever the meta runs)
 * @param threshold the threshold's name
 * @param property the watched value's name
 * @param value the value that crossed
 * @param below whether it went below ({@code false}: above)
 */
public record ThresholdEvent(
    Address entity,
    Address destination,
    long seq,
    long nanoTime,
    String threshold,
    String property,
    double value,
    boolean below)
    implements Notification {

  /** Checks the components. */
  public ThresholdEvent {
    requireNonNull(entity, "entity");
    requireNonNull(destination, "destination");
    requireNonNull(threshold, "threshold");
    requireNonNull(property, "property");
    Notifications.checkSeq(seq);
  }

  @Override
  public String kind() {
    return "threshold";
  }

  @Override
  public Map<String, Object> properties() {
    Map<String, Object> p = new LinkedHashMap<>();
    Notifications.common(p, this);
    p.put("threshold", threshold);
    p.put("property", property);
    p.put("value", value);
    p.put("below", below);
    return p;
  }
}

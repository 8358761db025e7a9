package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.LinkedHashMap;
import java.util.Map;
import org.armgals.active.Address;
import org.jspecify.annotations.Nullable;

/**
 * A notification of an action (paper §3.3, {@code ActionEvent}): the name of the behavior whose
 * activation led to it, and its input. A meta replays the behavior on its model: small, but a lost
 * one leaves the model wrong until it resynchronizes.
 *
 * @param entity the entity
 * @param destination its behavioral meta
 * @param seq its number in the entity's sequence
 * @param nanoTime the entity's time at the step it tells of, from its kernel's time source (the
 *     base level's clock: virtual time in a simulation, wherever the meta runs)
 * @param behavior the name of the behavior applied (a method name, a transition identifier)
 * @param input the behavior's input; a simple value (string, number, boolean) if the event is to
 *     cross runtimes
 */
public record ActionEvent(
    Address entity,
    Address destination,
    long seq,
    long nanoTime,
    String behavior,
    @Nullable Object input)
    implements Notification {

  /** Checks the components. */
  public ActionEvent {
    requireNonNull(entity, "entity");
    requireNonNull(destination, "destination");
    requireNonNull(behavior, "behavior");
    Notifications.checkSeq(seq);
  }

  @Override
  public String kind() {
    return "action";
  }

  @Override
  public Map<String, Object> properties() {
    Map<String, Object> p = new LinkedHashMap<>();
    Notifications.common(p, this);
    p.put("behavior", behavior);
    if (input instanceof String || input instanceof Number || input instanceof Boolean) {
      p.put("input", input);
    }
    return p;
  }
}

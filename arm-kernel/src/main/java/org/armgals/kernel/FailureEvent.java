package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.LinkedHashMap;
import java.util.Map;
import org.armgals.active.Address;

/**
 * A failure while the entity processed an event (docs/architecture.md, runtime semantics 8): always
 * notified to its behavioral meta, besides the runtime's error handler.
 *
 * @param entity the entity
 * @param destination its behavioral meta
 * @param seq its number in the entity's sequence
 * @param nanoTime the entity's time at the step it tells of, from its kernel's time source (the
 *     base level's clock: virtual time in a simulation, wherever the meta runs)
 * @param error the class name of the exception
 * @param message its message, empty if it had none
 * @param event what it was processing, as text; empty outside an event (a reactive cycle)
 */
public record FailureEvent(
    Address entity,
    Address destination,
    long seq,
    long nanoTime,
    String error,
    String message,
    String event)
    implements Notification {

  /** Checks the components. */
  public FailureEvent {
    requireNonNull(entity, "entity");
    requireNonNull(destination, "destination");
    requireNonNull(error, "error");
    requireNonNull(message, "message");
    requireNonNull(event, "event");
    Notifications.checkSeq(seq);
  }

  @Override
  public String kind() {
    return "failure";
  }

  @Override
  public Map<String, Object> properties() {
    Map<String, Object> p = new LinkedHashMap<>();
    Notifications.common(p, this);
    p.put("error", error);
    p.put("message", message);
    return p;
  }
}

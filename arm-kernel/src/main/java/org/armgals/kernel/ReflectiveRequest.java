package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.LinkedHashMap;
import java.util.Map;
import org.armgals.active.Address;
import org.jspecify.annotations.Nullable;

/**
 * A request for a reflective computation from a base entity to its behavioral meta (flow 2 of
 * §3.1), often to start an adaptation. An entity sends one when a behavior's result is a {@link
 * Reflect}.
 *
 * @param entity the entity
 * @param destination its behavioral meta
 * @param seq its number in the entity's sequence
 * @param nanoTime the entity's time at the step it tells of, from its kernel's time source (the
 *     base level's clock: virtual time in a simulation, wherever the meta runs)
 * @param subject what the entity asks about
 * @param argument a simple value, or {@code null}
 */
public record ReflectiveRequest(
    Address entity,
    Address destination,
    long seq,
    long nanoTime,
    String subject,
    @Nullable Object argument)
    implements Notification {

  /** Checks the components. */
  public ReflectiveRequest {
    requireNonNull(entity, "entity");
    requireNonNull(destination, "destination");
    requireNonNull(subject, "subject");
    Notifications.checkSeq(seq);
  }

  @Override
  public String kind() {
    return "reflect";
  }

  @Override
  public Map<String, Object> properties() {
    Map<String, Object> p = new LinkedHashMap<>();
    Notifications.common(p, this);
    p.put("subject", subject);
    return p;
  }
}

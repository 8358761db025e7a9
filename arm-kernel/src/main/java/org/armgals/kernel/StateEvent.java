package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.LinkedHashMap;
import java.util.Map;
import org.armgals.active.Address;
import org.jspecify.annotations.Nullable;

/**
 * A notification of a state (paper §3.3, {@code StateEvent}): what the entity's state looks like
 * after a step, at the entity's chosen grain. A meta replaces its model's state with what the
 * structural meta's {@code mapToState} makes of the observation: robust to lost events, bigger than
 * an action event.
 *
 * @param entity the entity
 * @param destination its behavioral meta
 * @param seq its number in the entity's sequence
 * @param nanoTime the entity's time at the step it tells of, from its kernel's time source (the
 *     base level's clock: virtual time in a simulation, wherever the meta runs)
 * @param behavior the behavior whose activation led to it; {@code null} for a snapshot sent on
 *     attachment or on a resynchronization request
 * @param observation the observed values: all of {@link org.armgals.representation.State#observe()}
 *     when {@code complete}, the ones of the grain otherwise
 * @param complete whether the observation is the whole state (a snapshot a model can resynchronize
 *     from)
 */
public record StateEvent(
    Address entity,
    Address destination,
    long seq,
    long nanoTime,
    @Nullable String behavior,
    Map<String, Object> observation,
    boolean complete)
    implements Notification {

  /** Checks and copies the components. */
  public StateEvent {
    requireNonNull(entity, "entity");
    requireNonNull(destination, "destination");
    observation = Map.copyOf(requireNonNull(observation, "observation"));
    Notifications.checkSeq(seq);
  }

  @Override
  public String kind() {
    return "state";
  }

  @Override
  public Map<String, Object> properties() {
    Map<String, Object> p = new LinkedHashMap<>(observation);
    Notifications.common(p, this);
    if (behavior != null) {
      p.put("behavior", behavior);
    }
    p.put("complete", complete);
    return p;
  }
}

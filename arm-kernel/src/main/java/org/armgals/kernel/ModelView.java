package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.Set;
import org.armgals.active.Address;
import org.armgals.representation.State;
import org.jspecify.annotations.Nullable;

/**
 * A snapshot of a behavioral meta's model of one base entity.
 *
 * @param entity the base entity
 * @param state the state the model believes the entity is in; {@code null} while it knows nothing
 *     (before the first state event, or when the last observation matched several states)
 * @param candidates the states the last observation may stand for (one when the model is sure)
 * @param lastSeq the last sequence number received from the entity, 0 if none
 * @param staleness how long since the model last integrated a notification from the entity, by the
 *     kernel's time source
 * @param resyncing whether the model is out of sync and waits for a complete state event
 * @param resyncRequests how many resynchronization requests it has sent
 * @param requestedVersion the version of the last adaptation request sent, 0 if none
 * @param appliedVersion the version the entity acknowledged having applied last, 0 if none
 * @param suppressedAdaptations how many adaptations the damping held back
 * @param filter the selector its notifications are judged by
 * @param lost whether the entity's runtime was reported lost or gone ({@link
 *     Kernel#presenceListener}) and the model has heard nothing from it since
 * @param refusedAdaptations how many adaptation requests the entity acknowledged as refused
 * @param lastRefusal why the entity refused the last one it refused; {@code null} if none
 * @param lockStep whether the entity runs in lock step with the meta ({@link
 *     EntityOptions#lockStep()}): its requests are handed over at its barriers
 */
public record ModelView(
    Address entity,
    @Nullable State state,
    Set<State> candidates,
    long lastSeq,
    Duration staleness,
    boolean resyncing,
    long resyncRequests,
    long requestedVersion,
    long appliedVersion,
    long suppressedAdaptations,
    String filter,
    boolean lost,
    long refusedAdaptations,
    @Nullable String lastRefusal,
    boolean lockStep) {

  /** Checks and copies the components. */
  public ModelView {
    requireNonNull(entity, "entity");
    candidates = Set.copyOf(requireNonNull(candidates, "candidates"));
    requireNonNull(staleness, "staleness");
    requireNonNull(filter, "filter");
  }
}

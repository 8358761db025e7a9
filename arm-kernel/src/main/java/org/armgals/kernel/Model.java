package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.Set;
import org.armgals.active.Address;
import org.armgals.active.Filter;
import org.armgals.representation.Activation;
import org.armgals.representation.Behaviors;
import org.armgals.representation.RepresentationException;
import org.armgals.representation.State;
import org.jspecify.annotations.Nullable;

/**
 * A behavioral meta's model of one base entity (paper §2.3, §3.3): an activation in the space of
 * the entity's structural meta, replaced by state events and advanced by replaying action events. A
 * gap in the sequence numbers, an observation that matches nothing, or an action that cannot be
 * replayed puts it out of sync; it then asks for a complete state, and asks again (at most once per
 * retry period, on each notification it receives) until one arrives: resync is level-triggered.
 *
 * <p>Confined to its behavioral meta's object.
 */
final class Model<S extends State> {
  private final Entity entity;
  private final StructuralMetaImpl<S> meta;
  private final Activation<S> activation;
  private final long retryNanos;
  final Governor governor;

  private Behaviors<S> harmonizedWith;
  private boolean known;
  private Set<S> candidates = Set.of();
  private long lastSeq;
  private long lastHeard;
  private long baseTime;
  private boolean lost;
  private boolean resyncing = true;
  private long lastAsk;
  private long resyncRequests;
  long requestedVersion;

  /** The requests the entity acknowledged as refused, and the reason of the last. */
  long refusedAdaptations;

  @org.jspecify.annotations.Nullable String lastRefusal;

  /** Whether the entity runs in lock step with this meta: its requests wait for its barrier. */
  boolean lockStep;

  /** In lock step, the requests decided since the entity's last barrier. */
  final java.util.List<AdaptationRequest> held = new java.util.ArrayList<>();

  long appliedVersion;
  Filter filter = Filter.ALL;

  /**
   * @param entity the base entity, of this runtime or a handle on one of another
   * @param meta the structural meta whose space the model is in: the entity's own, or for an entity
   *     of another runtime one of this kernel describing the same kind
   */
  Model(Entity entity, StructuralMetaImpl<S> meta, Damping damping, Duration retry, long now) {
    this.entity = requireNonNull(entity, "entity");
    this.meta = requireNonNull(meta, "meta");
    this.harmonizedWith = meta.behaviors();
    this.activation = meta.stateSpace().activate(meta.getInitialState(), harmonizedWith);
    this.retryNanos = retry.toNanos();
    this.governor = new Governor(damping);
    this.lastHeard = now;
    this.lastAsk = now; // attaching asks for the first complete state
  }

  Entity entity() {
    return entity;
  }

  /** Whether {@code n} was integrated already, or is older than what was: a duplicate. */
  boolean stale(Notification n) {
    return n.seq() <= lastSeq;
  }

  /**
   * Integrates {@code n} received at {@code now}.
   *
   * @return whether to send a resynchronization request now
   */
  boolean integrate(Notification n, long now) {
    if (n.seq() <= lastSeq) {
      return false; // already integrated, or older than what was
    }
    boolean gap = lastSeq != 0 && n.seq() != lastSeq + 1;
    lastSeq = n.seq();
    lastHeard = now;
    baseTime = n.nanoTime();
    lost = false;
    if (gap) {
      resyncing = true;
    }
    switch (n) {
      case StateEvent s -> replace(s);
      case ActionEvent a -> replay(a);
      default -> {}
    }
    if (resyncing && (gap || now - lastAsk >= retryNanos)) {
      lastAsk = now;
      resyncRequests++;
      return true;
    }
    return false;
  }

  private void replace(StateEvent s) {
    Set<S> found;
    try {
      found = meta.mapToState(s.observation(), known ? activation.state() : null);
    } catch (IllegalArgumentException e) {
      resyncing = true;
      return;
    }
    candidates = found;
    if (s.complete() && found.size() == 1) {
      activation.reset(found.iterator().next());
      known = true;
      resyncing = false;
    } else if (!resyncing) {
      if (found.size() == 1) {
        activation.reset(found.iterator().next());
      } else if (!found.contains(activation.state())) {
        known = false;
        resyncing = found.isEmpty();
      }
    }
  }

  private void replay(ActionEvent a) {
    if (resyncing || !known) {
      return;
    }
    Behaviors<S> now = meta.behaviors();
    if (now != harmonizedWith) {
      harmonizedWith = now;
      activation.harmonize(now);
    }
    try {
      activation.apply(a.behavior(), a.input());
      candidates = Set.of(activation.state());
    } catch (RepresentationException e) {
      resyncing = true;
    }
  }

  /** The entity's time at the last notification integrated (its clock); 0 before any. */
  long baseTime() {
    return baseTime;
  }

  long lastSeq() {
    return lastSeq;
  }

  /** Marks the entity lost with its runtime, until a notification from it is integrated. */
  void lost() {
    lost = true;
  }

  ModelView view(long now) {
    return new ModelView(
        entity.address(),
        known ? activation.state() : null,
        Set.<State>copyOf(candidates),
        lastSeq,
        Duration.ofNanos(Math.max(0, now - lastHeard)),
        resyncing,
        resyncRequests,
        requestedVersion,
        appliedVersion,
        governor.suppressed(),
        filter.expression(),
        lost,
        refusedAdaptations,
        lastRefusal,
        lockStep);
  }

  @Override
  public String toString() {
    return entity.name() + (known ? "=" + activation.state() : "=?");
  }

  Address address() {
    return entity.address();
  }

  @Nullable State believed() {
    return known ? activation.state() : null;
  }
}

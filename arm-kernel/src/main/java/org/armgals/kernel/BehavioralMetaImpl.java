package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.OptionalLong;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.Filter;
import org.armgals.active.Future;
import org.armgals.active.FutureValue;
import org.armgals.active.ObjectStoppedException;
import org.armgals.kernel.spi.MetaContext;
import org.armgals.kernel.spi.MetaPolicy;
import org.armgals.representation.State;
import org.armgals.representation.p.PState;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A behavioral meta-entity: the models of its base entities, their filters, its policy and the
 * damping of its adaptations. Models and filters are confined to its object; {@link #views} is what
 * other threads (JMX) read.
 */
final class BehavioralMetaImpl extends EntityImpl<PState> implements BehavioralMeta {
  private static final Logger LOG = LoggerFactory.getLogger(BehavioralMetaImpl.class);

  private final MetaPolicy policy;
  private final Damping damping;
  private final Map<Address, Model<?>> models = new LinkedHashMap<>();
  private final List<Entity> bases = new CopyOnWriteArrayList<>();
  final Map<Address, Published> views = new ConcurrentHashMap<>();
  private final MetaContext context = new Context();

  /** What the policy is handling now, if anything: the cause of what it decides. */
  private ReflectionEvent.@Nullable Cause cause;

  BehavioralMetaImpl(
      KernelImpl kernel,
      String name,
      StructuralMetaImpl<PState> meta,
      EntityServant<PState> servant,
      MetaPolicy policy,
      Damping damping) {
    super(kernel, name, meta, servant);
    this.policy = requireNonNull(policy, "policy");
    this.damping = requireNonNull(damping, "damping");
  }

  @Override
  boolean handle(Event event) throws Exception {
    switch (event) {
      case Notification n -> notified(n);
      case Wire.Barrier b -> barrier(b);
      case Wire.Free f -> free(f);
      case AdaptationAck a -> {
        Model<?> m = models.get(a.sender());
        if (m != null && a.applied() && a.version() > m.appliedVersion) {
          m.appliedVersion = a.version();
          publish(m);
        } else if (m != null && !a.applied()) {
          m.refusedAdaptations++;
          m.lastRefusal = a.failure();
          publish(m);
        }
      }
      default -> {
        return false;
      }
    }
    return true;
  }

  /**
   * Lock step: the entity has sent every notification of an instant, all handled now; from now on
   * the requests for it are held back and released in the answer to its next barrier.
   */
  private void barrier(Wire.Barrier b) throws Exception {
    Model<?> m = models.get(b.sender());
    List<AdaptationRequest> held = List.of();
    Exception failure = null;
    if (m != null) {
      m.lockStep = true;
      cause = new ReflectionEvent.Cause(m.entity().name(), b.seq(), b.nanoTime());
      try {
        policy.onInstant(context, b.sender(), b.instant());
      } catch (Exception e) {
        failure = e; // the barrier is answered all the same: the entity must not wait for nothing
      } finally {
        cause = null;
      }
      held = List.copyOf(m.held);
      m.held.clear();
      publish(m);
      if (kernel.listening()) {
        kernel.tell(
            new ReflectionEvent.Answered(name(), m.entity().name(), b.instant(), held.size()));
      }
    }
    try {
      kernel
          .runtime()
          .ref(b.replyTo())
          .send(new Wire.Released(address(), b.replyTo(), b.sender(), b.instant(), held));
    } catch (ObjectStoppedException e) {
      LOG.debug("answer to {} not delivered: the entity's kernel is closed", b);
    }
    if (failure != null) {
      throw failure;
    }
  }

  /** The entity runs free again: what was held goes as events. */
  private void free(Wire.Free f) {
    Model<?> m = models.get(f.sender());
    if (m != null) {
      m.lockStep = false;
      for (AdaptationRequest r : m.held) {
        sendTo(m.entity(), r);
      }
      m.held.clear();
      publish(m);
    }
  }

  private void notified(Notification n) throws Exception {
    Model<?> m = models.get(n.entity());
    if (m == null || m.stale(n)) {
      return; // from an entity deleted from this meta, still in flight; or a duplicate
    }
    long now = kernel.nanoTime();
    if (m.integrate(n, now)) {
      sendTo(m.entity(), new ResyncRequest(address(), n.entity(), m.lastSeq()));
    }
    publish(m);
    boolean passed = Selectors.matches(m.filter, n);
    if (kernel.listening()) {
      kernel.tell(new ReflectionEvent.Received(name(), m.entity().name(), n, passed));
    }
    if (passed) {
      cause = new ReflectionEvent.Cause(m.entity().name(), n.seq(), n.nanoTime());
      try {
        policy.onNotification(context, n);
      } finally {
        cause = null;
      }
    }
  }

  private void publish(Model<?> m) {
    long now = kernel.nanoTime();
    views.put(m.address(), new Published(m.view(now), now));
  }

  private Model<?> model(Address entity) {
    Model<?> m = models.get(requireNonNull(entity, "entity"));
    if (m == null) {
      throw new IllegalArgumentException(
          entity + " is not a base entity of " + name() + "; its base entities are " + bases);
    }
    return m;
  }

  /**
   * {@code entity} as a base entity this meta can take: an entity of its kernel, or a handle of its
   * kernel on an entity of another runtime.
   */
  private Entity base(Entity entity) {
    if (requireNonNull(entity, "entity").handle() instanceof RemoteEntity r
        && r.kernel() == kernel) {
      return r;
    }
    return kernel.own(entity);
  }

  private Model<?> newModel(Entity e) {
    StructuralMetaImpl<?> kind =
        e instanceof RemoteEntity r ? r.kind() : ((EntityImpl<?>) e).structuralMetaImpl();
    return newModel(e, kind);
  }

  private <S extends State> Model<S> newModel(Entity e, StructuralMetaImpl<S> kind) {
    return new Model<>(e, kind, damping, kernel.options().resyncRetry(), kernel.nanoTime());
  }

  /** Sends {@code event} to a base entity, of this runtime or of another. */
  private void sendTo(Entity e, Event event) {
    try {
      if (e instanceof EntityImpl<?> local) {
        local.object().send(event);
      } else {
        kernel.runtime().ref(e.address()).send(event);
      }
    } catch (ObjectStoppedException stopped) {
      LOG.debug("{} is stopped: {} not delivered", e, event);
    }
  }

  @Override
  public Future addBaseLevelEntity(Entity entity) {
    Entity e = base(entity);
    return object()
        .signal(
            own -> {
              if (models.containsKey(e.address())) {
                return;
              }
              if (e instanceof EntityImpl<?> local) {
                BehavioralMetaImpl previous = local.servant.meta();
                if (previous != null && previous != this) {
                  previous.deleteBaseLevelEntity(local);
                }
              }
              Model<?> m = newModel(e);
              models.put(e.address(), m);
              bases.add(e);
              publish(m);
              switch (e) {
                case EntityImpl<?> local -> local.object().send(s -> s.attach(this));
                case RemoteEntity remote -> {
                  remote.meta(this);
                  sendTo(remote, new Wire.Attach(address(), remote.address()));
                }
                default -> throw new IllegalStateException("not a base entity: " + e);
              }
              own.call(KernelBehaviors.ADD_BASE, e.name());
            });
  }

  @Override
  public Future deleteBaseLevelEntity(Entity entity) {
    Entity e = base(entity);
    return object()
        .signal(
            own -> {
              if (models.remove(e.address()) == null) {
                return;
              }
              bases.removeIf(b -> b.address().equals(e.address()));
              views.remove(e.address());
              switch (e) {
                case EntityImpl<?> local -> {
                  if (!local.isStopped()) {
                    local.object().send(s -> s.detach(this));
                  }
                }
                case RemoteEntity remote -> {
                  remote.meta(null);
                  sendTo(remote, new Wire.Detach(address(), remote.address()));
                }
                default -> throw new IllegalStateException("not a base entity: " + e);
              }
              own.call(KernelBehaviors.DELETE_BASE, e.name());
            });
  }

  @Override
  public List<Entity> baseLevelEntities() {
    return List.copyOf(bases);
  }

  @Override
  public Future setFilter(Entity entity, String selector) {
    Entity e = base(entity);
    Filter compiled = Filter.selector(selector);
    return object().signal(own -> swapFilter(e.address(), compiled, selector));
  }

  private void swapFilter(Address entity, Filter compiled, String selector) {
    Model<?> m = model(entity);
    m.filter = compiled;
    publish(m);
    if (kernel.listening()) {
      kernel.tell(new ReflectionEvent.FilterChanged(name(), m.entity().name(), selector, cause));
    }
  }

  @Override
  public FutureValue<ModelView> model(Entity entity) {
    Entity e = base(entity);
    return object().call(own -> model(e.address()).view(kernel.nanoTime()));
  }

  @Override
  public FutureValue<OptionalLong> adapt(Entity entity, Adaptation adaptation) {
    Entity e = base(entity);
    requireNonNull(adaptation, "adaptation");
    return object().call(own -> adaptNow(e.address(), adaptation));
  }

  private OptionalLong adaptNow(Address entity, Adaptation adaptation) {
    Model<?> m = model(entity);
    if (!m.governor.tryAdapt(baseNow(m))) {
      publish(m);
      if (kernel.listening()) {
        kernel.tell(new ReflectionEvent.Suppressed(name(), m.entity().name(), adaptation, cause));
      }
      return OptionalLong.empty();
    }
    long version = ++m.requestedVersion;
    AdaptationRequest request = new AdaptationRequest(address(), entity, version, adaptation);
    if (m.lockStep) {
      m.held.add(request);
    } else {
      sendTo(m.entity(), request);
    }
    publish(m);
    if (kernel.listening()) {
      kernel.tell(
          new ReflectionEvent.Requested(name(), m.entity().name(), request, cause, m.lockStep));
    }
    return OptionalLong.of(version);
  }

  /**
   * Now in the clock of {@code m}'s entity, for its damping: the time of what the policy handles,
   * if anything; else the kernel's time for an entity of this runtime (the same clock), and the
   * time of the entity's last notification for one of another runtime (whose clock this kernel
   * cannot read). So a meta damps in the base level's time wherever it runs.
   */
  private long baseNow(Model<?> m) {
    ReflectionEvent.Cause c = cause;
    if (c != null) {
      return c.nanoTime();
    }
    return m.entity() instanceof RemoteEntity ? m.baseTime() : kernel.nanoTime();
  }

  /**
   * Tells this meta that {@code runtime} is gone: every model of an entity living there is marked
   * lost, and the policy hears a {@link FailureEvent} for it, whatever the entity's filter (a loss
   * is always told, as failures are). The event's {@code error} is {@code error}, its {@code seq}
   * the last one the model integrated (it is not integrated itself).
   */
  void runtimeGone(String runtime, String error, String message) {
    requireNonNull(runtime, "runtime");
    object()
        .signal(
            own -> {
              for (Model<?> m : List.copyOf(models.values())) {
                if (!m.address().runtime().equals(runtime)) {
                  continue;
                }
                m.lost();
                publish(m);
                policy.onNotification(
                    context,
                    new FailureEvent(
                        m.address(),
                        address(),
                        Math.max(1, m.lastSeq()),
                        m.baseTime(),
                        error,
                        message,
                        ""));
              }
            });
  }

  long suppressed() {
    long total = 0;
    for (Published p : views.values()) {
      total += p.view().suppressedAdaptations();
    }
    return total;
  }

  /** A model's view as last published, and when, for readers on other threads. */
  record Published(ModelView view, long at) {
    /** How stale the model is at {@code now}. */
    java.time.Duration staleness(long now) {
      return view.staleness().plusNanos(Math.max(0, now - at));
    }
  }

  /** What the policy may do; used only on this meta's object. */
  private final class Context implements MetaContext {
    @Override
    public BehavioralMeta self() {
      return BehavioralMetaImpl.this;
    }

    @Override
    public Entity entity(Address entity) {
      return BehavioralMetaImpl.this.model(entity).entity();
    }

    @Override
    public ModelView model(Address entity) {
      return BehavioralMetaImpl.this.model(entity).view(kernel.nanoTime());
    }

    @Override
    public OptionalLong adapt(Address entity, Adaptation adaptation) {
      return adaptNow(entity, requireNonNull(adaptation, "adaptation"));
    }

    @Override
    public void setFilter(Address entity, String selector) {
      swapFilter(entity, Filter.selector(selector), selector);
    }

    @Override
    public long nanoTime() {
      ReflectionEvent.Cause c = cause;
      return c != null ? c.nanoTime() : kernel.nanoTime();
    }
  }

  /** The state each model believes, by entity name, for JMX. */
  Map<String, String> modelStates() {
    Map<String, String> m = new LinkedHashMap<>();
    for (Entity b : bases) {
      Published p = views.get(b.address());
      State s = p == null ? null : p.view().state();
      m.put(b.name(), s == null ? "?" : s.observe().toString());
    }
    return m;
  }
}

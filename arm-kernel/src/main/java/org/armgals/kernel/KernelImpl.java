package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.ObjectConfig;
import org.armgals.active.spi.NameService;
import org.armgals.active.spi.PresenceEvent;
import org.armgals.active.spi.PresenceListener;
import org.armgals.kernel.spi.MetaPolicy;
import org.armgals.kernel.spi.ReflectionListener;
import org.armgals.representation.Behaviors;
import org.armgals.representation.State;
import org.armgals.representation.StateSpace;
import org.armgals.representation.p.PSpace;
import org.armgals.representation.p.PState;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** The bootstrapped kernel: its four kernel entities and the registry of all its entities. */
final class KernelImpl implements Kernel {
  private static final Logger LOG = LoggerFactory.getLogger(KernelImpl.class);

  static final String ENTITY = "Entity";
  static final String STRUCTURAL_META = "StructuralMeta";
  static final String BEHAVIORAL_META = "BehavioralMeta";
  static final String BASIC_BEHAVIORAL_META = "basicBehavioralMeta";

  private final ActiveRuntime runtime;
  private final KernelOptions options;
  private final Set<String> names = ConcurrentHashMap.newKeySet();
  private final Map<Address, EntityImpl<?>> byAddress = new ConcurrentHashMap<>();
  private final Map<String, EntityImpl<?>> byName = new ConcurrentHashMap<>();
  private final Jmx jmx;
  private volatile boolean closed;

  // Set by bootstrap before the kernel is published: the kernel entities refer to each other.
  private StructuralMetaImpl<PState> entity;
  private StructuralMetaImpl<PState> structural;
  private StructuralMetaImpl<PState> behavioral;
  private BehavioralMetaImpl basic;

  private static final EntityOptions KERNEL_OPTIONS =
      EntityOptions.defaults().withNotification(NotificationPolicy.actionsOnly());

  private KernelImpl(ActiveRuntime runtime, KernelOptions options) {
    this.runtime = requireNonNull(runtime, "runtime");
    this.options = requireNonNull(options, "options");
    this.jmx = new Jmx(runtime.name(), options.jmx());
  }

  /**
   * ObjVlisp's bootstrap: make the four kernel entities, then tie the knots (StructuralMeta is its
   * own instance; basicBehavioralMeta is its own behavioral meta), then start them.
   */
  static Kernel bootstrap(ActiveRuntime runtime, KernelOptions options) {
    KernelImpl k = new KernelImpl(runtime, options);
    List<String> structuralNames = List.copyOf(KernelBehaviors.STRUCTURAL.names());
    k.structural = k.kernelMeta(STRUCTURAL_META, KernelBehaviors.STRUCTURAL, structuralNames);
    k.entity = k.kernelMeta(ENTITY, KernelBehaviors.ENTITY, structuralNames);
    k.behavioral = k.kernelMeta(BEHAVIORAL_META, KernelBehaviors.BEHAVIORAL, structuralNames);
    k.structural.instanceOf(k.structural);
    k.entity.instanceOf(k.structural);
    k.behavioral.instanceOf(k.structural);
    k.structural.inherit(k.entity);
    k.behavioral.inherit(k.entity);
    k.basic =
        new BehavioralMetaImpl(
            k,
            BASIC_BEHAVIORAL_META,
            k.behavioral,
            k.servant(
                KernelBehaviors.BEHAVIORAL_SPACE,
                KernelBehaviors.behavioral(BASIC_BEHAVIORAL_META),
                KernelBehaviors.BEHAVIORAL),
            MetaPolicy.MODEL_ONLY,
            Damping.none());
    for (EntityImpl<PState> e : List.of(k.structural, k.entity, k.behavioral)) {
      k.structural.adopt(e);
    }
    k.behavioral.adopt(k.basic);
    for (EntityImpl<PState> e : List.of(k.structural, k.entity, k.behavioral, k.basic)) {
      k.reserve(e.name());
      e.start(KERNEL_OPTIONS.config());
      k.register(e);
    }
    for (EntityImpl<PState> e : List.of(k.structural, k.entity, k.behavioral)) {
      k.structural.describe(KernelBehaviors.NEW_INSTANCE, e.name());
    }
    k.behavioral.describe(KernelBehaviors.NEW_INSTANCE, k.basic.name());
    for (EntityImpl<PState> e : List.of(k.structural, k.entity, k.behavioral, k.basic)) {
      k.basic.addBaseLevelEntity(e).touch();
      e.settle();
    }
    return k;
  }

  private StructuralMetaImpl<PState> kernelMeta(
      String name, Behaviors<PState> ofInstances, List<String> ownBehaviorNames) {
    StructuralMetaImpl.Makes makes;
    PSpace space;
    switch (name) {
      case STRUCTURAL_META -> {
        makes = StructuralMetaImpl.Makes.STRUCTURAL_METAS;
        space = KernelBehaviors.STRUCTURAL_SPACE;
      }
      case BEHAVIORAL_META -> {
        makes = StructuralMetaImpl.Makes.BEHAVIORAL_METAS;
        space = KernelBehaviors.BEHAVIORAL_SPACE;
      }
      default -> {
        makes = StructuralMetaImpl.Makes.ENTITIES;
        space = KernelBehaviors.ENTITY_SPACE;
      }
    }
    return new StructuralMetaImpl<>(
        this,
        name,
        null,
        servant(
            KernelBehaviors.STRUCTURAL_SPACE,
            KernelBehaviors.structural(name, List.copyOf(ofInstances.names())),
            KernelBehaviors.STRUCTURAL),
        space,
        ofInstances,
        null,
        makes);
  }

  /** The servant of a kernel meta-entity: its description in {@code space} and its methods. */
  private EntityServant<PState> servant(PSpace space, PState initial, Behaviors<PState> behaviors) {
    return new EntityServant<>(space.activate(initial, behaviors), KERNEL_OPTIONS);
  }

  @Override
  public <S extends State> StructuralMeta<S> newStructuralMeta(
      String name, StateSpace<S> space, Behaviors<S> behaviors) {
    requireNonNull(space, "space");
    requireNonNull(behaviors, "behaviors");
    StructuralMetaImpl<PState> of = structural;
    StructuralMetaImpl<PState> parent = entity;
    StructuralMetaImpl<S> made =
        of.instantiate(
            name,
            KernelBehaviors.structural(name, List.copyOf(behaviors.names())),
            KERNEL_OPTIONS,
            servant ->
                new StructuralMetaImpl<>(
                    this,
                    name,
                    of,
                    servant,
                    space,
                    behaviors,
                    parent,
                    StructuralMetaImpl.Makes.ENTITIES));
    basic.addBaseLevelEntity(made).touch();
    made.settle();
    return made;
  }

  @Override
  public PresenceListener presenceListener() {
    return this::presence;
  }

  private void presence(PresenceEvent event) {
    String message;
    switch (event) {
      case PresenceEvent.Lost lost ->
          message = "runtime '" + lost.runtime() + "' lost: silent for " + lost.silence();
      case PresenceEvent.Left left -> message = "runtime '" + left.runtime() + "' left";
      case PresenceEvent.Joined joined -> {
        return;
      }
    }
    for (EntityImpl<?> e : byAddress.values()) {
      if (e.isStopped()) {
        continue;
      }
      if (e instanceof BehavioralMetaImpl meta) {
        meta.runtimeGone(event.runtime(), event.getClass().getName(), message);
      }
      e.servant.metaGone(event.runtime(), message);
    }
  }

  @Override
  public BehavioralMeta newBehavioralMeta(String name, MetaPolicy policy, Damping damping) {
    requireNonNull(policy, "policy");
    requireNonNull(damping, "damping");
    StructuralMetaImpl<PState> of = behavioral;
    BehavioralMetaImpl made =
        of.instantiate(
            name,
            KernelBehaviors.behavioral(name),
            KERNEL_OPTIONS,
            servant -> new BehavioralMetaImpl(this, name, of, servant, policy, damping));
    basic.addBaseLevelEntity(made).touch();
    made.settle();
    return made;
  }

  /** Takes a name for a new entity, or says why not. */
  void reserve(String name) {
    requireNonNull(name, "name");
    if (closed) {
      throw new IllegalStateException("the kernel is closed; no entity '" + name + "' made");
    }
    if (name.isBlank()) {
      throw new IllegalArgumentException("an entity name must not be blank, was '" + name + "'");
    }
    if (!names.add(name)) {
      throw new IllegalArgumentException(
          "an entity named '" + name + "' exists already; expected a new name");
    }
  }

  void register(EntityImpl<?> e) {
    byAddress.put(e.address(), e);
    byName.put(e.name(), e);
    jmx.register(e);
  }

  /** {@code entity} as an entity of this kernel, or an exception saying what it is. */
  EntityImpl<?> own(Entity entity) {
    requireNonNull(entity, "entity");
    if (entity.handle() instanceof EntityImpl<?> e && e.kernel == this) {
      return e;
    }
    throw new IllegalArgumentException(
        entity + " is not an entity of this kernel (runtime " + runtime.name() + ")");
  }

  BehavioralMetaImpl own(BehavioralMeta meta) {
    if (own((Entity) meta) instanceof BehavioralMetaImpl b) {
      return b;
    }
    throw new IllegalArgumentException(meta + " is not a behavioral meta of this kernel");
  }

  KernelOptions options() {
    return options;
  }

  long nanoTime() {
    return options.timeSource().nanoTime();
  }

  /** Whether a listener hears the reflective loop: events are made only then. */
  boolean listening() {
    return options.listener() != ReflectionListener.NONE;
  }

  /** Tells the listener {@code event}; a failure of the listener is logged, never thrown. */
  void tell(ReflectionEvent event) {
    try {
      options.listener().on(event);
    } catch (RuntimeException e) {
      LOG.warn("the reflection listener failed on {}", event, e);
    }
  }

  @Override
  public ActiveRuntime runtime() {
    return runtime;
  }

  @Override
  public StructuralMeta<?> entity() {
    return entity;
  }

  @Override
  public StructuralMeta<?> structuralMeta() {
    return structural;
  }

  @Override
  public StructuralMeta<?> behavioralMeta() {
    return behavioral;
  }

  @Override
  public BehavioralMeta basicBehavioralMeta() {
    return basic;
  }

  @Override
  public Optional<Entity> lookupEntity(Address address) {
    return Optional.ofNullable(byAddress.get(requireNonNull(address, "address")));
  }

  @Override
  public Optional<Entity> lookupEntity(String name) {
    return Optional.ofNullable(byName.get(requireNonNull(name, "name")));
  }

  @Override
  public Entity remoteEntity(String name, Address address, StructuralMeta<?> kind) {
    requireNonNull(name, "name");
    requireNonNull(address, "address");
    if (address.runtime().equals(runtime.name())) {
      throw new IllegalArgumentException(
          address + " is of this runtime (" + runtime.name() + "); expected one of another");
    }
    if (!(own(requireNonNull(kind, "kind")) instanceof StructuralMetaImpl<?> k)) {
      throw new IllegalArgumentException(kind + " is not a structural meta of this kernel");
    }
    return new RemoteEntity(this, name, address, k);
  }

  @Override
  public Entity lookupRemote(NameService names, String name, StructuralMeta<?> kind) {
    requireNonNull(names, "names");
    requireNonNull(name, "name");
    requireNonNull(kind, "kind");
    return remoteEntity(name, names.lookup(name).getValue(), kind);
  }

  private @Nullable ActiveObject<LockStepDesk> desk;

  /** The lock-step desk of this kernel, spawned at first use. */
  synchronized ActiveObject<LockStepDesk> lockStepDesk() {
    ActiveObject<LockStepDesk> d = desk;
    if (d == null) {
      d = runtime.spawn(new LockStepDesk(), ObjectConfig.asynchronous());
      desk = d;
    }
    return d;
  }

  @Override
  public void close() {
    if (closed) {
      return;
    }
    closed = true;
    for (EntityImpl<?> e : new ArrayList<>(byAddress.values())) {
      e.object().stop();
    }
    synchronized (this) {
      if (desk != null) {
        desk.stop();
      }
    }
    jmx.close();
  }
}

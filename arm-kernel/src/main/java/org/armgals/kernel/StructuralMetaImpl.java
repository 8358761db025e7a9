package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Function;
import java.util.function.UnaryOperator;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.Future;
import org.armgals.active.Mode;
import org.armgals.active.ObjectStoppedException;
import org.armgals.representation.Behavior;
import org.armgals.representation.Behaviors;
import org.armgals.representation.State;
import org.armgals.representation.StateSpace;
import org.armgals.representation.p.PState;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A structural meta-entity: the space and the behaviors of its instances, and the instances
 * themselves, which it harmonizes when the behaviors change.
 *
 * <p>The behaviors and the list of instances change under {@link #lock}, so that an instance made
 * concurrently with a change either starts with the new behaviors or is harmonized with them.
 */
final class StructuralMetaImpl<S extends State> extends EntityImpl<PState>
    implements StructuralMeta<S> {

  /** What its instances are: plain entities, or meta-entities made by the kernel itself. */
  enum Makes {
    ENTITIES,
    STRUCTURAL_METAS,
    BEHAVIORAL_METAS
  }

  private static final Logger LOG = LoggerFactory.getLogger(StructuralMetaImpl.class);

  private final StateSpace<S> space;
  private final Makes makes;
  private final Object lock = new Object();
  private final List<EntityImpl<S>> instances = new CopyOnWriteArrayList<>();
  private volatile Behaviors<S> behaviors;
  private final List<Address> twins = new CopyOnWriteArrayList<>();
  private volatile @Nullable Behaviors<S> catalog;
  private @Nullable StructuralMetaImpl<?> superMeta;

  StructuralMetaImpl(
      KernelImpl kernel,
      String name,
      @Nullable StructuralMetaImpl<PState> meta,
      EntityServant<PState> servant,
      StateSpace<S> space,
      Behaviors<S> behaviors,
      @Nullable StructuralMetaImpl<?> superMeta,
      Makes makes) {
    super(kernel, name, meta, servant);
    this.space = requireNonNull(space, "space");
    this.behaviors = requireNonNull(behaviors, "behaviors");
    this.superMeta = superMeta;
    this.makes = makes;
  }

  /** Bootstrap only: {@code StructuralMeta} is made before {@code Entity}, which it extends. */
  void inherit(StructuralMetaImpl<?> parent) {
    this.superMeta = parent;
  }

  /** Bootstrap only: an instance made by hand. */
  void adopt(EntityImpl<S> instance) {
    synchronized (lock) {
      instances.add(instance);
    }
  }

  /**
   * Makes, starts and registers an instance with the current behaviors, and describes it in this
   * meta's own state.
   */
  <T extends EntityImpl<S>> T instantiate(
      String name, S initial, EntityOptions options, Function<EntityServant<S>, T> maker) {
    kernel.reserve(name);
    T entity;
    synchronized (lock) {
      EntityServant<S> servant = new EntityServant<>(space.activate(initial, behaviors), options);
      entity = maker.apply(servant);
      entity.start(options.config());
      instances.add(entity);
    }
    kernel.register(entity);
    describe(KernelBehaviors.NEW_INSTANCE, name);
    return entity;
  }

  @Override
  public StateSpace<S> stateSpace() {
    return space;
  }

  @Override
  public Behaviors<S> behaviors() {
    return behaviors;
  }

  @Override
  public Optional<Behavior<S>> lookup(String behaviorName) {
    return behaviors.lookup(requireNonNull(behaviorName, "name"));
  }

  @Override
  public Future addBehavior(Behavior<S> behavior) {
    requireNonNull(behavior, "behavior");
    return object()
        .signal(
            own -> {
              change(b -> b.with(behavior));
              own.call(KernelBehaviors.ADD_BEHAVIOR, behavior.name());
              mirror(behavior.name(), true);
            });
  }

  @Override
  public Future deleteBehavior(String behaviorName) {
    requireNonNull(behaviorName, "name");
    return object()
        .signal(
            own -> {
              change(b -> b.without(behaviorName));
              own.call(KernelBehaviors.DELETE_BEHAVIOR, behaviorName);
              mirror(behaviorName, false);
            });
  }

  @Override
  public Future mirrorTo(Address twin) {
    requireNonNull(twin, "twin");
    if (twin.runtime().equals(kernel.runtime().name())) {
      throw new IllegalArgumentException(
          twin + " is of this runtime (" + kernel.runtime().name() + "); expected one of another");
    }
    return object().signal(own -> twins.add(twin));
  }

  @Override
  public Future catalog(Behaviors<S> allowed) {
    requireNonNull(allowed, "catalog");
    return object().signal(own -> catalog = allowed);
  }

  /** Flow 4 to the twins of other runtimes: the change, by name; on this object. */
  private void mirror(String behaviorName, boolean add) {
    for (Address twin : twins) {
      kernel.runtime().ref(twin).send(new Wire.Modify(address(), twin, behaviorName, add));
    }
  }

  @Override
  boolean handle(Event event) {
    if (!(event instanceof Wire.Modify m)) {
      return false;
    }
    if (m.add()) {
      Behaviors<S> allowed = catalog;
      Behavior<S> behavior = allowed == null ? null : allowed.lookup(m.behavior()).orElse(null);
      if (behavior == null) {
        throw new IllegalArgumentException(
            name()
                + " refuses to add '"
                + m.behavior()
                + "' for "
                + m.sender()
                + ": not in its catalog "
                + (allowed == null ? "(none set)" : allowed.names()));
      }
      change(b -> b.with(behavior));
      servant.call(KernelBehaviors.ADD_BEHAVIOR, m.behavior());
    } else {
      change(b -> b.without(m.behavior()));
      servant.call(KernelBehaviors.DELETE_BEHAVIOR, m.behavior());
    }
    return true;
  }

  /** Flows 4 and 5: replaces the behaviors and harmonizes every instance; on this object. */
  private void change(UnaryOperator<Behaviors<S>> how) {
    synchronized (lock) {
      Behaviors<S> next = how.apply(behaviors);
      behaviors = next;
      for (EntityImpl<S> instance : instances) {
        try {
          instance.object().send(s -> s.harmonize(next));
        } catch (ObjectStoppedException e) {
          LOG.debug("{} is stopped: not harmonized", instance);
        }
      }
    }
  }

  @Override
  public S getInitialState() {
    return space.initialState();
  }

  @Override
  public Set<S> mapToState(Map<String, ?> observation, @Nullable S current) {
    return space.mapToState(requireNonNull(observation, "observation"), current);
  }

  @Override
  public Optional<StructuralMeta<?>> superMeta() {
    return Optional.ofNullable(superMeta);
  }

  @Override
  public List<Entity> instances() {
    return List.copyOf(instances);
  }

  @Override
  public Entity newEntity(String entityName, BehavioralMeta meta) {
    return newEntity(entityName, meta, EntityOptions.defaults());
  }

  @Override
  public Entity newEntity(String entityName, EntityOptions options) {
    requireNonNull(options, "options");
    checkMakesEntities();
    return instantiate(
        entityName,
        space.initialState(),
        options,
        servant -> new PlainEntity<>(kernel, entityName, this, servant));
  }

  private void checkMakesEntities() {
    if (makes != Makes.ENTITIES) {
      throw new UnsupportedOperationException(
          name()
              + " makes "
              + makes.name().toLowerCase(java.util.Locale.ROOT)
              + "; use Kernel.newStructuralMeta or Kernel.newBehavioralMeta");
    }
  }

  @Override
  public Entity newEntity(String entityName, BehavioralMeta meta, EntityOptions options) {
    requireNonNull(options, "options");
    BehavioralMetaImpl m = kernel.own(meta);
    checkMakesEntities();
    PlainEntity<S> e =
        instantiate(
            entityName,
            space.initialState(),
            options,
            servant -> new PlainEntity<>(kernel, entityName, this, servant));
    m.addBaseLevelEntity(e).touch();
    if (options.config().mode() == Mode.ASYNCHRONOUS) {
      e.settle(); // a reactive entity takes its attachment at its clock's next release
    }
    return e;
  }
}

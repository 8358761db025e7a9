package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.Optional;
import org.armgals.active.ActiveContext;
import org.armgals.active.ActiveObject;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.FutureValue;
import org.armgals.active.ObjectConfig;
import org.armgals.active.spi.ObjectListener;
import org.armgals.representation.State;
import org.jspecify.annotations.Nullable;

/**
 * An entity: a handle on the active object whose servant is an {@link EntityServant}. The three
 * kinds differ only in the events their object handles besides the base ones ({@link #handle}).
 *
 * <p>Its structural meta and object are set once, before the handle is published.
 */
abstract sealed class EntityImpl<E extends State> implements Entity
    permits PlainEntity, StructuralMetaImpl, BehavioralMetaImpl {

  final KernelImpl kernel;
  final EntityServant<E> servant;
  private final String name;
  private @Nullable StructuralMetaImpl<E> structuralMeta;
  private @Nullable ActiveObject<EntityServant<E>> object;

  EntityImpl(
      KernelImpl kernel,
      String name,
      @Nullable StructuralMetaImpl<E> structuralMeta,
      EntityServant<E> servant) {
    this.kernel = requireNonNull(kernel, "kernel");
    this.name = requireNonNull(name, "name");
    this.structuralMeta = structuralMeta;
    this.servant = requireNonNull(servant, "servant");
    servant.owner(this);
  }

  /** Bootstrap only: the structural meta of a kernel entity made before it. */
  final void instanceOf(StructuralMetaImpl<E> meta) {
    this.structuralMeta = meta;
  }

  /** Spawns its object; the kernel's listener notifies failures to the behavioral meta. */
  final void start(ObjectConfig config) {
    ObjectListener user = config.listener();
    ObjectListener kernelListener =
        new ObjectListener() {
          @Override
          public void onDropped(
              Address o, Event event, org.armgals.active.OverflowPolicy overflow) {
            user.onDropped(o, event, overflow);
          }

          @Override
          public void onFailed(Address o, @Nullable Event event, Throwable error) {
            try {
              user.onFailed(o, event, error);
            } finally {
              servant.failed(event, error);
            }
          }
        };
    this.object = kernel.runtime().spawn(servant, config.withListener(kernelListener));
  }

  /** The events of its kind besides the base ones; on its object. */
  boolean handle(Event event) throws Exception {
    return false;
  }

  final ActiveObject<EntityServant<E>> object() {
    return requireNonNull(object, "object");
  }

  final StructuralMetaImpl<E> structuralMetaImpl() {
    return requireNonNull(structuralMeta, "structuralMeta");
  }

  /** Returns once its object has processed every event sent to it before. */
  final void settle() {
    object().call(s -> Boolean.TRUE).getValue();
  }

  /** Sends its own object a reified behavior of its kind (the kernel describing itself). */
  final void describe(String behavior, String argument) {
    object().send(s -> s.call(behavior, argument));
  }

  @Override
  public final String name() {
    return name;
  }

  @Override
  public final Address address() {
    return object().address();
  }

  @Override
  public final StructuralMeta<?> structuralMeta() {
    return structuralMetaImpl();
  }

  @Override
  public final Optional<BehavioralMeta> behavioralMeta() {
    return Optional.ofNullable(servant.meta());
  }

  @Override
  public final State state() {
    return servant.current();
  }

  @Override
  public final NotificationPolicy notificationPolicy() {
    return servant.policy();
  }

  @Override
  public final long appliedVersion() {
    return servant.appliedVersion();
  }

  @Override
  public final void send(String trigger, @Nullable Object input) {
    requireNonNull(trigger, "trigger");
    Address sender = ActiveContext.current().map(o -> o.address()).orElse(null);
    object().send(new Stimulus(sender, address(), trigger, input));
  }

  @Override
  public final FutureValue<@Nullable Object> call(String behavior, @Nullable Object input) {
    requireNonNull(behavior, "behavior");
    return object().call(s -> s.call(behavior, input));
  }

  @Override
  public final boolean isStopped() {
    return object().isStopped();
  }

  @Override
  public final int queueDepth() {
    return object().queueDepth();
  }

  @Override
  public String toString() {
    return name + "@" + address();
  }
}

package org.armgals.kernel;

import java.util.Optional;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.spi.AllowList;
import org.armgals.active.spi.NameService;
import org.armgals.active.spi.PresenceListener;
import org.armgals.kernel.spi.MetaPolicy;
import org.armgals.representation.Behaviors;
import org.armgals.representation.State;
import org.armgals.representation.StateSpace;

/**
 * A bootstrapped ARM kernel (paper figure 2), made by {@link StructuralMeta#bootstrap}: the three
 * structural meta-entities, the basic behavioral meta-entity, and the way to create new kinds of
 * entities and new behavioral meta-entities the same way the kernel made its own.
 *
 * <p>Threading: every method may be called from any thread.
 */
public interface Kernel extends AutoCloseable {

  /** The runtime the kernel's entities live in. */
  ActiveRuntime runtime();

  /** {@code Entity}: the structural meta-entity describing what all entities have in common. */
  StructuralMeta<?> entity();

  /** {@code StructuralMeta}: the structural meta of all structural meta-entities, itself too. */
  StructuralMeta<?> structuralMeta();

  /** {@code BehavioralMeta}: the structural meta of all behavioral meta-entities. */
  StructuralMeta<?> behavioralMeta();

  /** {@code basicBehavioralMeta}: the behavioral meta of all kernel entities, itself included. */
  BehavioralMeta basicBehavioralMeta();

  /**
   * A new kind of entity: a structural meta-entity, instance of {@link #structuralMeta()},
   * inheriting from {@link #entity()}, whose behavioral meta is {@link #basicBehavioralMeta()}.
   *
   * @param name a name, unique among the kernel's entities
   * @param space the states of its instances
   * @param behaviors the behaviors its instances start with
   * @throws IllegalArgumentException a blank or taken name
   */
  <S extends State> StructuralMeta<S> newStructuralMeta(
      String name, StateSpace<S> space, Behaviors<S> behaviors);

  /**
   * A new behavioral meta-entity: an instance of {@link #behavioralMeta()}, whose own behavioral
   * meta is {@link #basicBehavioralMeta()}.
   *
   * @param name a name, unique among the kernel's entities
   * @param policy what it does with the notifications of its base entities
   * @param damping how often it may adapt one base entity
   * @throws IllegalArgumentException a blank or taken name
   */
  BehavioralMeta newBehavioralMeta(String name, MetaPolicy policy, Damping damping);

  /** The kernel's entity at {@code address}, if there is one. */
  Optional<Entity> lookupEntity(Address address);

  /** The kernel's entity named {@code name}, if there is one. */
  Optional<Entity> lookupEntity(String name);

  /**
   * A handle on an entity of another runtime's kernel (the distributed case of paper §2.3, decision
   * 0024): a behavioral meta of this kernel can take it as a base entity ({@link
   * BehavioralMeta#addBaseLevelEntity}), model it, filter and adapt it; {@link Entity#send} and
   * {@link Entity#call} reach it through the runtime's transport. Both runtimes must allow the
   * kernel's events on their transports ({@link #allowKernelEvents}).
   *
   * @param name the entity's name (in its own kernel)
   * @param address its address, in another runtime
   * @param kind a structural meta of this kernel describing the entity's kind: the same state space
   *     and behaviors as the entity's own structural meta (behaviors are code and do not cross
   *     runtimes; both sides know the kind), in which its models are built
   * @throws IllegalArgumentException the address is of this runtime, or {@code kind} is not a
   *     structural meta of this kernel
   */
  Entity remoteEntity(String name, Address address, StructuralMeta<?> kind);

  /**
   * {@link #remoteEntity} for the entity registered under {@code name} in the name service of
   * {@code names} (registered there by its runtime with {@code names.register(entity.name(),
   * entity.address())}). Blocks until the name service answers.
   *
   * @throws org.armgals.active.FutureTimeoutException no runtime answers for {@code name} within
   *     the transport's reply timeout
   */
  Entity lookupRemote(NameService names, String name, StructuralMeta<?> kind);

  /**
   * Adds every kernel event to the allow-list of {@code builder}, each on its topic: notifications
   * ({@link StateEvent}, {@link ActionEvent}, {@link ThresholdEvent}, {@link FailureEvent}, {@link
   * ReflectiveRequest}) and {@link AdaptationAck}s, which go to behavioral metas, on {@code
   * arm/BMeta}; adaptation and resynchronization requests, stimuli, attachments and calls, which go
   * to base entities, on {@code arm/Entity}; and the values they hold.
   *
   * @return {@code builder}
   */
  static <B extends AllowList> B allowKernelEvents(B builder) {
    return Wire.allow(builder);
  }

  /**
   * The kernel's ear on runtime presence (decision 0028), to add to this runtime's presence (the
   * JMS transport's {@code org.armgals.active.jms.Presence}): when a runtime is reported {@link
   * org.armgals.active.spi.PresenceEvent.Lost lost} or {@link
   * org.armgals.active.spi.PresenceEvent.Left gone}, every behavioral meta of this kernel that
   * models an entity living there marks that model lost ({@link ModelView#lost()}) and its policy
   * hears a {@link FailureEvent} whose {@code error} is the presence event's class name and whose
   * message names the runtime. Joins are ignored: a model stops being lost when it next hears from
   * its entity.
   */
  PresenceListener presenceListener();

  /**
   * Stops every entity of the kernel and unregisters their MBeans; the runtime itself is left
   * running (it belongs to whoever made it). Idempotent.
   */
  @Override
  void close();
}

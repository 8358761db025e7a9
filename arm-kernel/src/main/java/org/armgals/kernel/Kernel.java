package org.armgals.kernel;

import java.util.Optional;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
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
   * Stops every entity of the kernel and unregisters their MBeans; the runtime itself is left
   * running (it belongs to whoever made it). Idempotent.
   */
  @Override
  void close();
}

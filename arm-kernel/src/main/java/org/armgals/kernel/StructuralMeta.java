package org.armgals.kernel;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Future;
import org.armgals.representation.Behavior;
import org.armgals.representation.Behaviors;
import org.armgals.representation.State;
import org.armgals.representation.StateSpace;
import org.jspecify.annotations.Nullable;

/**
 * A structural meta-entity (paper §3.1, §4.2): it holds the structural part of the reified
 * representation of its instances (their {@link StateSpace} and {@link Behaviors}), which it shares
 * among them, and it is itself an entity.
 *
 * <p>Behaviors change at run time: {@link #addBehavior} and {@link #deleteBehavior} are events to
 * this meta-entity (flow 4 of §3.1, usually sent by a behavioral meta), which replaces the set of
 * behaviors and harmonizes every instance with it (flow 5): an instance applies the new set from
 * the first event it processes after the harmonization event. Lookup, the initial state and {@code
 * mapToState} read the immutable structure directly and never wait.
 *
 * <p>Threading: every method may be called from any thread.
 *
 * @param <S> the state type of its instances
 */
public interface StructuralMeta<S extends State> extends Entity {

  /**
   * Builds the kernel of figure 2 in {@code runtime} with the default options: see {@link
   * #bootstrap(ActiveRuntime, KernelOptions)}.
   */
  static Kernel bootstrap(ActiveRuntime runtime) {
    return bootstrap(runtime, KernelOptions.defaults());
  }

  /**
   * Builds the kernel as in ObjVlisp: {@code StructuralMeta} is its own instance; {@code Entity},
   * {@code StructuralMeta} and {@code BehavioralMeta} are structural meta-entities (instances of
   * {@code StructuralMeta}), the latter two inheriting from {@code Entity}; {@code
   * basicBehavioralMeta} is an instance of {@code BehavioralMeta} and the behavioral meta of all
   * four, itself included.
   */
  static Kernel bootstrap(ActiveRuntime runtime, KernelOptions options) {
    return KernelImpl.bootstrap(runtime, options);
  }

  /** The states of its instances. */
  StateSpace<S> stateSpace();

  /** The behaviors of its instances now (an immutable set). */
  Behaviors<S> behaviors();

  /** The behavior of its instances named {@code name}, if there is one now. */
  Optional<Behavior<S>> lookup(String name);

  /**
   * Teaches all its instances {@code behavior} (replacing one of the same name). The future
   * completes once every instance has been sent the harmonization event.
   */
  Future addBehavior(Behavior<S> behavior);

  /**
   * Makes all its instances lose the behavior named {@code name}. The future fails with {@link
   * org.armgals.representation.NoSuchBehaviorException} if there is none.
   */
  Future deleteBehavior(String name);

  /**
   * Sends every later {@link #addBehavior} and {@link #deleteBehavior} of this structural meta, by
   * behavior name, to the structural meta at {@code twin}, in another runtime, which makes the same
   * change from its {@linkplain #catalog catalog} and harmonizes its own instances (flows 4 and 5
   * across runtimes, decision 0024). Typically this structural meta is the copy of a kind with
   * which a behavioral meta models entities of another runtime, and {@code twin} is the kind of
   * those entities. Behaviors are code: only their names cross.
   */
  Future mirrorTo(Address twin);

  /**
   * The behaviors a structural meta of another runtime may add to this one by name ({@link
   * #mirrorTo}); empty (the default) refuses every remote addition. Deletions by name are always
   * accepted. A refused modification is a failure of this structural meta, notified to its
   * behavioral meta.
   */
  Future catalog(Behaviors<S> catalog);

  /** The state its instances start in. */
  S getInitialState();

  /**
   * The states of an instance that the observation carried by a state event may stand for; see
   * {@link StateSpace#mapToState}.
   */
  Set<S> mapToState(Map<String, ?> observation, @Nullable S current);

  /** The structural meta-entity it inherits from ("extends"); empty for {@code Entity}. */
  Optional<StructuralMeta<?>> superMeta();

  /** Its instances now, in creation order. */
  List<Entity> instances();

  /**
   * A new instance, in its initial state, with the current behaviors, meta-of {@code meta}, with
   * the default options ({@link EntityOptions#defaults()}).
   */
  Entity newEntity(String name, BehavioralMeta meta);

  /**
   * A new instance, in its initial state, with the current behaviors, whose behavioral meta is
   * {@code meta} (the entity is added to it as by {@link BehavioralMeta#addBaseLevelEntity}). An
   * asynchronous entity is returned attached to its meta; a synchronous (reactive) one takes its
   * attachment at its clock's next release, before any event sent to it after this call.
   *
   * @throws IllegalArgumentException a blank or taken name
   * @throws UnsupportedOperationException this structural meta makes meta-entities (use {@link
   *     Kernel#newStructuralMeta} or {@link Kernel#newBehavioralMeta})
   */
  Entity newEntity(String name, BehavioralMeta meta, EntityOptions options);

  /**
   * A new instance with no behavioral meta yet, for one of another runtime to take (decision 0024:
   * {@link BehavioralMeta#addBaseLevelEntity} on a handle from {@link Kernel#lookupRemote}), or one
   * of this runtime: it notifies no one, and in lock step waits for no one, until a meta takes it.
   * Unlike {@link #newEntity(String, BehavioralMeta, EntityOptions)} with the basic meta, no local
   * attachment is on its way when the remote one arrives, so the entity ends with the meta that
   * took it, whatever the order in which its first release takes the two.
   *
   * @throws IllegalArgumentException a blank or taken name
   * @throws UnsupportedOperationException this structural meta makes meta-entities
   */
  Entity newEntity(String name, EntityOptions options);
}

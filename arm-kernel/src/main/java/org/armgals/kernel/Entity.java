package org.armgals.kernel;

import java.util.Optional;
import org.armgals.active.Address;
import org.armgals.active.FutureValue;
import org.armgals.representation.State;
import org.jspecify.annotations.Nullable;

/**
 * An entity of the ARM (paper §3.1, §4.2): an active object whose main behavior, {@code process},
 * runs its {@link org.armgals.representation.Activation activation} on the events it receives, with
 * behaviors its structural meta-entity gives it and may change while it runs, and which notifies
 * its behavioral meta-entity of what it does.
 *
 * <p>"Instance of" means "has as structural meta" ({@link #structuralMeta()}); "meta-of" means "has
 * as behavioral meta" ({@link #behavioralMeta()}). Structural and behavioral meta-entities are
 * entities too.
 *
 * <p>An entity is made by composition over {@link org.armgals.active.ActiveRuntime}, not by
 * subclassing: {@link StructuralMeta#newEntity} spawns an active object whose servant holds the
 * activation; this handle is a reference to it. Threading: every method may be called from any
 * thread; the activation itself is touched only by the entity's own object.
 */
public interface Entity {

  /** Its name, unique in its kernel. */
  String name();

  /** Its address in the runtime (the sender of its notifications). */
  Address address();

  /** Its structural meta-entity: it is an instance of it. */
  StructuralMeta<?> structuralMeta();

  /**
   * Its behavioral meta-entity, which receives its notifications; empty once it has been deleted
   * from its meta and added to no other, and while its meta is in another runtime (decision 0024:
   * its notifications go there all the same). For a handle on an entity of another runtime ({@link
   * Kernel#remoteEntity}): the meta of this kernel that took it, if any.
   */
  Optional<BehavioralMeta> behavioralMeta();

  /**
   * Its current state, as of the last event it finished processing (a snapshot published by the
   * entity's own object: reading it never waits).
   */
  State state();

  /** What it notifies its behavioral meta of, and at which grain, now. */
  NotificationPolicy notificationPolicy();

  /** The version of the last adaptation request it applied; 0 before any. */
  long appliedVersion();

  /**
   * Sends it a stimulus (a {@link Stimulus} event): it reacts by dispatching {@code trigger} to its
   * activation (a method, a transition, a statechart step). One-way; a failure is notified to its
   * behavioral meta.
   */
  void send(String trigger, @Nullable Object input);

  /**
   * Asks it to apply the behavior named {@code behavior} (looked up in the behaviors its structural
   * meta gave it) and answers the behavior's result. Synchronized: the future fails with the cause
   * if the behavior is unknown or not applicable, and the failure is notified to its behavioral
   * meta.
   */
  FutureValue<@Nullable Object> call(String behavior, @Nullable Object input);

  /** Whether its object has been stopped. */
  boolean isStopped();

  /**
   * How many events wait in its buffer now (a reactive entity takes them at its next release); -1
   * for a handle on an entity of another runtime, whose buffer this runtime cannot see.
   */
  int queueDepth();

  /**
   * The kernel's own handle on this entity: itself, unless this object stands for an entity the
   * kernel made and forwards to it (a robot is the kernel entity whose program it is; a robot's
   * behavioral meta is the kernel meta-entity whose policy it is), in which case it answers that
   * entity. The kernel takes every entity given to it through this handle.
   *
   * @throws IllegalStateException the object stands for no entity yet (a robot not started)
   */
  default Entity handle() {
    return this;
  }
}

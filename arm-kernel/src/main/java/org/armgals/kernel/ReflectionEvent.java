package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import org.jspecify.annotations.Nullable;

/**
 * One step of the reflective loop (paper §5.4, figure 8), as the kernel tells it to a {@link
 * org.armgals.kernel.spi.ReflectionListener}: a base entity notifies its behavioral meta, the meta
 * receives the notification and judges it with its filter, changes a filter, requests an adaptation
 * (or its damping holds one back), and the entity applies or refuses the request at its adaptation
 * point. Base-side events name the instant of the entity's clock they happened in; meta-side events
 * name what the meta was handling when it decided ({@link Cause}: a notification, or the end of an
 * instant in lock step), in the base level's time, so that a recorder can put both sides on one
 * time line even when the meta runs in another runtime.
 *
 * <p>Entities are named by their names in their kernel: a meta names a base entity of another
 * runtime by the name its handle was given ({@link Kernel#remoteEntity}).
 */
public sealed interface ReflectionEvent {

  /** The name of the entity the event is about. */
  String entity();

  /**
   * What a meta was handling when it did something: the notification numbered {@code seq} from
   * {@code entity}, or, in lock step, the end of that entity's instant whose last notification is
   * numbered {@code seq}; {@code nanoTime} is the entity's time then (the base level's clock).
   */
  record Cause(String entity, long seq, long nanoTime) {
    /** Checks the components. */
    public Cause {
      requireNonNull(entity, "entity");
    }
  }

  /**
   * Base side: {@code entity} sent its behavioral meta {@code notification} during its instant
   * {@code instant} (0 for an entity without a clock).
   */
  record Notified(String entity, long instant, Notification notification)
      implements ReflectionEvent {
    /** Checks the components. */
    public Notified {
      requireNonNull(entity, "entity");
      requireNonNull(notification, "notification");
    }
  }

  /**
   * Meta side: {@code meta} received {@code notification} from {@code entity}, integrated it in its
   * model, and its filter let it through to the policy ({@code passed}) or not.
   */
  record Received(String meta, String entity, Notification notification, boolean passed)
      implements ReflectionEvent {
    /** Checks the components. */
    public Received {
      requireNonNull(meta, "meta");
      requireNonNull(entity, "entity");
      requireNonNull(notification, "notification");
    }
  }

  /**
   * Meta side: {@code meta} replaced its filter of {@code entity}'s notifications by {@code
   * selector}, because of {@code cause} (null: from outside its policy).
   */
  record FilterChanged(String meta, String entity, String selector, @Nullable Cause cause)
      implements ReflectionEvent {
    /** Checks the components. */
    public FilterChanged {
      requireNonNull(meta, "meta");
      requireNonNull(entity, "entity");
      requireNonNull(selector, "selector");
    }
  }

  /**
   * Meta side: {@code meta} requested {@code request} of {@code entity} because of {@code cause}
   * (null: from outside its policy); {@code held} in lock step, where it goes with the answer to
   * the entity's next barrier.
   */
  record Requested(
      String meta, String entity, AdaptationRequest request, @Nullable Cause cause, boolean held)
      implements ReflectionEvent {
    /** Checks the components. */
    public Requested {
      requireNonNull(meta, "meta");
      requireNonNull(entity, "entity");
      requireNonNull(request, "request");
    }
  }

  /**
   * Meta side: the {@link Damping} of {@code meta} held {@code adaptation} of {@code entity} back
   * (no request was sent), because of {@code cause} (null: from outside its policy).
   */
  record Suppressed(String meta, String entity, Adaptation adaptation, @Nullable Cause cause)
      implements ReflectionEvent {
    /** Checks the components. */
    public Suppressed {
      requireNonNull(meta, "meta");
      requireNonNull(entity, "entity");
      requireNonNull(adaptation, "adaptation");
    }
  }

  /**
   * Meta side, in lock step: {@code meta} has handled every notification of {@code entity}'s
   * instant {@code instant} and answered its barrier with {@code released} requests, for the
   * entity's adaptation point {@code k} instants later.
   */
  record Answered(String meta, String entity, long instant, int released)
      implements ReflectionEvent {
    /** Checks the components. */
    public Answered {
      requireNonNull(meta, "meta");
      requireNonNull(entity, "entity");
    }
  }

  /**
   * Base side: at its adaptation point of instant {@code instant}, {@code entity} applied {@code
   * request} ({@code refusal} null) or refused it ({@code refusal} says why). {@code nanos} is the
   * time it took, by the kernel's stopwatch ({@link KernelOptions#stopwatch()}); {@code overrun}
   * whether the adaptation point had by then spent more than the entity's clock period (the
   * adaptation did not fit in the cycle's time budget).
   */
  record Applied(
      String entity,
      long instant,
      AdaptationRequest request,
      @Nullable String refusal,
      long nanos,
      boolean overrun)
      implements ReflectionEvent {
    /** Checks the components. */
    public Applied {
      requireNonNull(entity, "entity");
      requireNonNull(request, "request");
    }

    /** Whether the request was applied (not refused). */
    public boolean applied() {
      return refusal == null;
    }
  }

  /**
   * Base side: {@code entity}, in lock step with its meta, stopped waiting for it at instant {@code
   * instant} and runs free from then on, keeping its last program: the meta did not answer in time,
   * or its runtime was reported lost or gone ({@code reason} says which).
   */
  record WentFree(String entity, long instant, String reason) implements ReflectionEvent {
    /** Checks the components. */
    public WentFree {
      requireNonNull(entity, "entity");
      requireNonNull(reason, "reason");
    }
  }

  /**
   * Base side: the runtime of {@code entity}'s behavioral meta was reported lost or gone ({@link
   * Kernel#presenceListener}); the entity goes on with its last program.
   */
  record MetaLost(String entity, String runtime, String reason) implements ReflectionEvent {
    /** Checks the components. */
    public MetaLost {
      requireNonNull(entity, "entity");
      requireNonNull(runtime, "runtime");
      requireNonNull(reason, "reason");
    }
  }
}

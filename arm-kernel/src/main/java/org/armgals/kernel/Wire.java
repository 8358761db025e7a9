package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.util.Map;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.Request;
import org.armgals.active.spi.AllowList;
import org.jspecify.annotations.Nullable;

/**
 * What the kernel sends between runtimes besides its public events (decision 0024): a behavioral
 * meta's attachment and detachment of a base entity of another runtime, and the requests with which
 * a {@link RemoteEntity} handle calls and inspects its entity. Their types stay package-private;
 * {@link #allow} puts them, with the public events, on a transport's allow-list.
 */
final class Wire {
  private Wire() {}

  /** A behavioral meta ({@code sender}) takes the entity ({@code destination}). */
  record Attach(Address sender, Address destination) implements Event {
    Attach {
      requireNonNull(sender, "sender");
      requireNonNull(destination, "destination");
    }
  }

  /** A behavioral meta ({@code sender}) lets go of the entity ({@code destination}). */
  record Detach(Address sender, Address destination) implements Event {
    Detach {
      requireNonNull(sender, "sender");
      requireNonNull(destination, "destination");
    }
  }

  /**
   * A structural modification from a structural meta ({@code sender}) to its twin in another
   * runtime ({@code destination}): add the behavior of that name from the twin's catalog, or delete
   * it.
   */
  record Modify(Address sender, Address destination, String behavior, boolean add)
      implements Event {
    Modify {
      requireNonNull(sender, "sender");
      requireNonNull(destination, "destination");
      requireNonNull(behavior, "behavior");
    }
  }

  /** {@link Entity#call} on an entity of another runtime; answers the behavior's result. */
  record Call(
      @Nullable Address sender, Address destination, String behavior, @Nullable Object input)
      implements Request<@Nullable Object> {
    Call {
      requireNonNull(destination, "destination");
      requireNonNull(behavior, "behavior");
    }
  }

  /** Asks an entity of another runtime for a {@link Report}. */
  record Inspect(@Nullable Address sender, Address destination) implements Request<Report> {
    Inspect {
      requireNonNull(destination, "destination");
    }
  }

  /**
   * Lock step ({@link EntityOptions#lockStep()}): the entity ({@code sender}) has sent its meta
   * ({@code destination}) every notification of its instant {@code instant}, the last numbered
   * {@code seq}, at its time {@code nanoTime}. Once the meta has handled them it sends {@code
   * replyTo} (the entity's kernel's lock-step desk) a {@link Released} with the adaptation requests
   * it decided since the entity's previous barrier (held back from the first barrier on instead of
   * sent as events). Sent on the meta's topic, behind the notifications it closes.
   */
  record Barrier(
      Address sender, Address destination, long instant, long seq, long nanoTime, Address replyTo)
      implements Event {
    Barrier {
      requireNonNull(sender, "sender");
      requireNonNull(destination, "destination");
      requireNonNull(replyTo, "replyTo");
    }
  }

  /**
   * A meta's answer to the barrier of {@code entity}'s instant {@code instant}: the requests it
   * decided on that instant's notifications, for the entity's adaptation point {@code k} instants
   * later.
   */
  record Released(
      Address sender,
      Address destination,
      Address entity,
      long instant,
      java.util.List<AdaptationRequest> requests)
      implements Event {
    Released {
      requireNonNull(sender, "sender");
      requireNonNull(destination, "destination");
      requireNonNull(entity, "entity");
      requests = java.util.List.copyOf(requests);
    }
  }

  /**
   * A lock-step entity ({@code sender}) stopped waiting for its meta ({@code destination}): the
   * meta sends it the requests it holds, and later ones, as events again.
   */
  record Free(Address sender, Address destination) implements Event {
    Free {
      requireNonNull(sender, "sender");
      requireNonNull(destination, "destination");
    }
  }

  /**
   * What an entity says of itself to a handle in another runtime: its whole observed state, its
   * notification policy and its applied version.
   */
  record Report(Map<String, Object> observation, NotificationPolicy policy, long appliedVersion) {
    Report {
      observation = Map.copyOf(requireNonNull(observation, "observation"));
      requireNonNull(policy, "policy");
    }
  }

  /**
   * Allows every kernel event on {@code builder}, each on the topic of decision 0024; adaptation
   * requests and their acknowledgements travel at least once (decision 0042).
   */
  static <B extends AllowList> B allow(B builder) {
    requireNonNull(builder, "builder");
    for (Class<? extends Event> toMeta :
        java.util.List.<Class<? extends Event>>of(
            StateEvent.class,
            ActionEvent.class,
            ThresholdEvent.class,
            FailureEvent.class,
            ReflectiveRequest.class,
            AdaptationAck.class,
            Barrier.class,
            Free.class)) {
      builder.allow("arm/BMeta", toMeta);
    }
    builder.allow("arm/SMeta", Modify.class);
    builder.atLeastOnce(AdaptationRequest.class, AdaptationAck.class);
    builder.allow(
        AdaptationRequest.class,
        ResyncRequest.class,
        Stimulus.class,
        Attach.class,
        Detach.class,
        Call.class,
        Inspect.class,
        Report.class,
        Released.class,
        Adaptation.SetNotification.class,
        Adaptation.ApplyBehavior.class,
        NotificationPolicy.class,
        Threshold.class);
    return builder;
  }
}

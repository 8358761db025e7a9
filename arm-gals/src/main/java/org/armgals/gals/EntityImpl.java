package org.armgals.gals;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.armgals.active.ActiveContext;
import org.armgals.active.ActiveObject;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.FutureEvent;
import org.armgals.active.FutureValue;
import org.armgals.active.ReactiveCycle;
import org.armgals.active.Request;
import org.armgals.active.ServantFunction;
import org.armgals.active.SynchronousFutureValue;
import org.jspecify.annotations.Nullable;

/**
 * A reactive entity: the servant of a synchronous active object. Its reactions, inbox, awaited
 * values and trace lines are touched by its own thread during an instant and by the island's
 * stepping thread between instants (adaptation, trace collection); the clock's release and the
 * end-of-instant wait order the two.
 */
final class EntityImpl<S> implements ReactiveEntity<S>, EventProcessor, ReactiveCycle {
  private final String name;
  private final S state;
  private final IslandImpl island;
  private final Map<String, Reaction<S>> reactions = new LinkedHashMap<>();
  private final List<Object> inbox = new ArrayList<>();
  private final List<Pending<?>> pending = new ArrayList<>();
  private final List<String> traceLines = new ArrayList<>();
  private volatile List<String> reactionNames = List.of();
  private @Nullable Answer<S> answerer;
  private @Nullable ActiveObject<EntityImpl<S>> object;

  EntityImpl(String name, S state, IslandImpl island, Reaction<S> main) {
    this.name = name;
    this.state = state;
    this.island = island;
    reactions.put("main", main);
    reactionNames = List.of("main");
  }

  void bind(ActiveObject<EntityImpl<S>> object) {
    this.object = object;
  }

  ActiveObject<EntityImpl<S>> object() {
    ActiveObject<EntityImpl<S>> o = object;
    if (o == null) {
      throw new IllegalStateException("entity " + name + " is not bound to its object yet");
    }
    return o;
  }

  S state() {
    return state;
  }

  // ---- the public face

  @Override
  public String name() {
    return name;
  }

  @Override
  public Address address() {
    return object().address();
  }

  @Override
  public Island island() {
    return island;
  }

  @Override
  public void send(Object payload) {
    requireNonNull(payload, "payload");
    Address sender = ActiveContext.current().map(ActiveObject::address).orElse(null);
    object().send(new Emission(sender, address(), payload));
  }

  @Override
  public <R extends @Nullable Object> FutureValue<R> query(ServantFunction<? super S, R> query) {
    requireNonNull(query, "query");
    return object().call(e -> query.apply(e.state));
  }

  @Override
  public void addReaction(String name, Reaction<S> reaction) {
    requireNonNull(name, "name");
    requireNonNull(reaction, "reaction");
    island.request(
        new PendingAdaptation(
            this,
            "addReaction " + name,
            () -> {
              cancelAwaitedBy(name);
              reactions.put(name, reaction);
              reactionNames = List.copyOf(reactions.keySet());
            }));
  }

  @Override
  public void removeReaction(String name) {
    requireNonNull(name, "name");
    island.request(
        new PendingAdaptation(
            this,
            "removeReaction " + name,
            () -> {
              if (reactions.remove(name) == null) {
                traceLines.add("removeReaction " + name + ": no such reaction");
                return;
              }
              cancelAwaitedBy(name);
              reactionNames = List.copyOf(reactions.keySet());
            }));
  }

  @Override
  public void adapt(String description, Consumer<? super S> change) {
    requireNonNull(description, "description");
    requireNonNull(change, "change");
    island.request(new PendingAdaptation(this, description, () -> change.accept(state)));
  }

  @Override
  public void answerWith(Answer<S> answer) {
    requireNonNull(answer, "answer");
    island.request(new PendingAdaptation(this, "answerWith", () -> answerer = answer));
  }

  @Override
  public List<String> reactions() {
    return reactionNames;
  }

  private void cancelAwaitedBy(String reaction) {
    for (Iterator<Pending<?>> it = pending.iterator(); it.hasNext(); ) {
      Pending<?> p = it.next();
      if (p.reaction.equals(reaction)) {
        p.cancel();
        it.remove();
        traceLines.add("cancelled a value awaited by " + reaction);
      }
    }
  }

  // ---- the servant

  @Override
  public void process(Event event) {
    switch (event) {
      case Emission s -> inbox.add(s.payload());
      case FutureEvent f -> {
        // its SynchronousFutureValue is done now; Pending reads it at the next onCycle
      }
      default ->
          throw new IllegalArgumentException(
              "a reactive entity takes payloads sent with send or emit, not " + event);
    }
  }

  @Override
  public @Nullable Object answer(Request<?> request) throws Exception {
    Answer<S> a = answerer;
    if (a == null) {
      throw new UnsupportedOperationException(
          "reactive entity "
              + name
              + " answers no requests (see answerWith); it was asked "
              + request);
    }
    if (island.tracing()) {
      traceLines.add("asked " + request);
    }
    return a.answer(state, request);
  }

  @Override
  public void onCycle(long instant) {
    for (Iterator<Pending<?>> it = pending.iterator(); it.hasNext(); ) {
      Pending<?> p = it.next();
      if (p.settle(instant)) {
        it.remove();
        if (p.status() == AwaitedValue.Status.TIMED_OUT) {
          traceLines.add("a value awaited by " + p.reaction + " timed out");
        }
      }
    }
    boolean tracing = island.tracing();
    if (tracing && !inbox.isEmpty()) {
      traceLines.add("in " + inbox);
    }
    Context context = new Context(instant, List.copyOf(inbox));
    for (Map.Entry<String, Reaction<S>> r : reactions.entrySet()) {
      context.reaction = r.getKey();
      try {
        r.getValue().react(context);
      } catch (Exception e) {
        island.failed(this, r.getKey(), instant, e);
        traceLines.add(r.getKey() + " failed: " + e);
      }
    }
    inbox.clear();
  }

  /** Hands the lines of the last cycle to {@code sink} and forgets them. */
  void drainTrace(Consumer<String> sink) {
    for (String line : traceLines) {
      sink.accept(name + " " + line);
    }
    traceLines.clear();
  }

  @Override
  public String toString() {
    return "ReactiveEntity[" + island.name() + "/" + name + "]";
  }

  private final class Context implements CycleContext<S> {
    private final long instant;
    private final List<Object> inputs;
    private String reaction = "";

    Context(long instant, List<Object> inputs) {
      this.instant = instant;
      this.inputs = inputs;
    }

    @Override
    public long instant() {
      return instant;
    }

    @Override
    public S state() {
      return state;
    }

    @Override
    public List<Object> inputs() {
      return inputs;
    }

    @Override
    public void emit(ReactiveEntity<?> target, Object payload) {
      requireNonNull(target, "target");
      requireNonNull(payload, "payload");
      EntityImpl<?> t = (EntityImpl<?>) target;
      t.object().send(new Emission(address(), t.address(), payload));
    }

    @Override
    public void emit(Address target, Object payload) {
      requireNonNull(target, "target");
      requireNonNull(payload, "payload");
      island.runtime().ref(target).send(new Emission(address(), target, payload));
    }

    @Override
    public <T, R extends @Nullable Object> AwaitedValue<R> call(
        ReactiveEntity<T> target, ServantFunction<? super T, R> query, Duration timeout) {
      requireNonNull(target, "target");
      requireNonNull(query, "query");
      requireNonNull(timeout, "timeout");
      if (timeout.isNegative() || timeout.isZero()) {
        throw new IllegalArgumentException("timeout must be > 0, was " + timeout);
      }
      EntityImpl<T> t = (EntityImpl<T>) target;
      FutureValue<R> f = t.object().call(e -> query.apply(e.state));
      if (!(f instanceof SynchronousFutureValue<R> sf)) {
        throw new IllegalStateException(
            "call must be made from a reaction of " + name + ", on its thread; got " + f);
      }
      long periods = island.periodsIn(timeout);
      Pending<R> p = new Pending<>(reaction, instant + periods, sf);
      pending.add(p);
      return p;
    }

    @Override
    public <R extends @Nullable Object> AwaitedValue<R> ask(
        Address target, Request<R> request, Duration timeout) {
      requireNonNull(target, "target");
      requireNonNull(request, "request");
      requireNonNull(timeout, "timeout");
      if (timeout.isNegative() || timeout.isZero()) {
        throw new IllegalArgumentException("timeout must be > 0, was " + timeout);
      }
      FutureValue<R> f = island.runtime().ref(target).ask(request);
      Pending<R> p = new Pending<>(reaction, instant + island.periodsIn(timeout), f);
      pending.add(p);
      return p;
    }

    @Override
    public void trace(String line) {
      requireNonNull(line, "line");
      if (island.tracing()) {
        traceLines.add(reaction + ": " + line);
      }
    }

    @Override
    public boolean tracing() {
      return island.tracing();
    }
  }
}

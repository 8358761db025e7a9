package org.armgals.kernel;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.armgals.active.ActiveObject;
import org.armgals.active.Address;
import org.armgals.active.Clock;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.ManualClock;
import org.armgals.active.ObjectStoppedException;
import org.armgals.active.ReactiveCycle;
import org.armgals.active.Request;
import org.armgals.active.TimeSource;
import org.armgals.kernel.spi.InstantContext;
import org.armgals.kernel.spi.ReactiveProgram;
import org.armgals.representation.Activation;
import org.armgals.representation.Behaviors;
import org.armgals.representation.State;
import org.armgals.representation.Step;
import org.armgals.representation.sc.Configuration;
import org.armgals.representation.sc.Statechart;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The servant of an entity's active object: {@link #process} is the entity's main behavior (paper
 * §4.2). It runs the activation, notifies the behavioral meta of each step as the notification
 * policy says, applies adaptation requests and harmonizes with its structural meta.
 *
 * <p>Its behavioral meta is either of this runtime ({@link #meta} and its address) or of another
 * one (its address only, decision 0024): notifications go to the address in both cases.
 *
 * <p>A reactive entity may have a {@link ReactiveProgram}: at each release it takes the events
 * waiting (stimuli are kept for the program, not dispatched), then, in {@link #onCycle}, applies
 * the adaptations due at the beginning of the cycle, runs the program, applies those due at the
 * end, and in lock step sends its meta the instant's barrier (see {@link EntityOptions}).
 *
 * <p>Threading: everything but the volatile snapshots ({@link #current}, {@link #policy}, {@link
 * #meta}, {@link #metaAddress}, {@link #appliedVersion}) is confined to the entity's object.
 */
final class EntityServant<E extends State> implements EventProcessor, ReactiveCycle {
  private static final Logger LOG = LoggerFactory.getLogger(EntityServant.class);

  private final Activation<E> activation;
  private final AdaptationPoint adaptationPoint;
  private final @Nullable ReactiveProgram program;
  private final Duration lockStepTimeout;
  private final int lockStep;
  private final long budgetNanos;
  private boolean lockStepping = true;
  private @Nullable EntityImpl<E> owner;

  private volatile E current;
  private volatile NotificationPolicy policy;
  private volatile @Nullable BehavioralMetaImpl meta;
  private volatile @Nullable Address metaAddress;
  private volatile long appliedVersion;
  private volatile long adaptationOverruns;
  private volatile long adaptationMaxNanos;

  private long seq;
  private @Nullable Map<String, Object> lastObserved;
  private final Map<String, Boolean> below = new HashMap<>();
  private final ArrayDeque<AdaptationRequest> pending = new ArrayDeque<>();
  private boolean instantBegun;
  private int toLose;
  private long instant;
  private final @Nullable LockStepGate gate;
  private boolean gateRegistered;
  private final List<Stimulus> stimuli = new ArrayList<>();
  private final InstantContext instantContext = new Instant();

  EntityServant(Activation<E> activation, EntityOptions options) {
    this.activation = requireNonNull(activation, "activation");
    this.adaptationPoint = options.adaptationPoint();
    this.program = options.program();
    this.lockStep = options.lockStep();
    this.lockStepTimeout = options.lockStepTimeout();
    this.gate = lockStepGate(options);
    Clock clock = options.config().clock();
    this.budgetNanos = clock == null ? Long.MAX_VALUE : clock.period().toNanos();
    this.policy = options.notification();
    this.current = activation.state();
  }

  void owner(EntityImpl<E> entity) {
    this.owner = entity;
  }

  private EntityImpl<E> owner() {
    return requireNonNull(owner, "owner");
  }

  E current() {
    return current;
  }

  NotificationPolicy policy() {
    return policy;
  }

  @Nullable BehavioralMetaImpl meta() {
    return meta;
  }

  @Nullable Address metaAddress() {
    return metaAddress;
  }

  long appliedVersion() {
    return appliedVersion;
  }

  /**
   * How many adaptation points took longer than the entity's clock period applying their requests
   * (the cycle's time budget), by the kernel's stopwatch.
   */
  long adaptationOverruns() {
    return adaptationOverruns;
  }

  /** The longest an adaptation point took applying its requests, by the kernel's stopwatch. */
  long adaptationMaxNanos() {
    return adaptationMaxNanos;
  }

  /** How many times a lock-step adaptation point gave up waiting for the meta. */
  long lockStepTimeouts() {
    LockStepGate g = gate;
    return g == null ? 0 : g.timeouts();
  }

  /**
   * Lock step needs virtual time: the gate waits at the releases of a manual clock. Under any other
   * clock the entity runs free.
   */
  private static @Nullable LockStepGate lockStepGate(EntityOptions options) {
    if (options.lockStep() == 0 || !(options.config().clock() instanceof ManualClock clock)) {
      return null;
    }
    LockStepGate g = new LockStepGate(options.lockStep(), options.lockStepTimeout());
    clock.addReleaseGate(g);
    return g;
  }

  Behaviors<E> behaviors() {
    return activation.behaviors();
  }

  @Override
  public void process(Event event) throws Exception {
    beginInstant();
    switch (event) {
      case Stimulus s -> {
        if (program != null) {
          stimuli.add(s);
        } else {
          for (Step<E> step : activation.dispatch(s.trigger(), s.input())) {
            stepped(step, s.input());
          }
        }
      }
      case AdaptationRequest r -> {
        pending.add(r);
        if (adaptationPoint == AdaptationPoint.ON_ARRIVAL) {
          applyPending();
        }
      }
      case ResyncRequest r -> snapshot();
      case Wire.Attach a -> attachRemote(a.sender());
      case Wire.Detach d -> {
        if (d.sender().equals(metaAddress)) {
          meta = null;
          metaAddress = null;
        }
      }
      default -> {
        if (!owner().handle(event)) {
          throw new IllegalArgumentException(
              "entity '"
                  + owner().name()
                  + "' cannot process "
                  + event
                  + "; expected a Stimulus, an AdaptationRequest or a ResyncRequest");
        }
      }
    }
  }

  @Override
  public @Nullable Object answer(Request<?> request) {
    return switch (request) {
      case Wire.Call c -> call(c.behavior(), c.input());
      case Wire.Inspect i -> new Wire.Report(current.observe(), policy, appliedVersion);
      default ->
          throw new IllegalArgumentException(
              "entity '" + owner().name() + "' cannot answer " + request + "; expected a call");
    };
  }

  @Override
  public void onCycle(long instant) throws Exception {
    if (program != null) {
      programCycle(program, instant);
      return;
    }
    if (adaptationPoint == AdaptationPoint.END_OF_CYCLE
        || (adaptationPoint == AdaptationPoint.BEGIN_OF_CYCLE && !instantBegun)) {
      applyPending();
    }
    instantBegun = false;
  }

  /**
   * One instant of an entity with a program: the adaptation point if at the beginning, the program,
   * the adaptation point if at the end, then the instant's barrier in lock step. A failure of the
   * program is rethrown after the rest, so that the runtime reports it and the entity goes on.
   */
  private void programCycle(ReactiveProgram p, long n) throws Exception {
    this.instant = n;
    Exception failure = null;
    try {
      if (adaptationPoint == AdaptationPoint.BEGIN_OF_CYCLE) {
        adaptationPoint(n);
      }
      try {
        p.react(instantContext);
      } catch (Exception e) {
        failure = e;
      }
      if (adaptationPoint == AdaptationPoint.END_OF_CYCLE) {
        adaptationPoint(n);
      }
      sendBarrier(n);
    } finally {
      stimuli.clear();
      instantBegun = false;
    }
    if (failure != null) {
      throw failure;
    }
  }

  /** In lock step, takes the meta's answers due at instant {@code n}; then applies. */
  private void adaptationPoint(long n) {
    LockStepGate g = gate;
    if (g != null && lockStepping) {
      pending.addAll(g.take(n - lockStep));
      if (g.free()) {
        goFree(n, g.reason());
      }
    }
    applyPending();
  }

  /**
   * A release gave up waiting for the meta: the entity runs free from now on (its reactive level
   * goes on without its meta), tells the meta so, and reports the failure to it.
   */
  private void goFree(long n, String reason) {
    lockStepping = false;
    Address m = metaAddress;
    LOG.warn(
        "entity '{}' stops waiting for its meta at instant {}: {}; it runs free from now on",
        owner().name(),
        n,
        reason);
    if (owner().kernel.listening()) {
      owner().kernel.tell(new ReflectionEvent.WentFree(owner().name(), n, reason));
    }
    if (m != null) {
      send(m, new Wire.Free(owner().address(), m));
    }
    failed(
        null,
        new IllegalStateException("lock step with the meta lost at instant " + n + ": " + reason));
  }

  /**
   * The runtime {@code runtime} was reported lost or gone: if this entity's meta lives there, the
   * entity tells the listener and, in lock step, stops waiting for it at once (it goes free at its
   * next adaptation point). On the presence thread.
   */
  void metaGone(String runtime, String message) {
    Address m = metaAddress;
    if (m == null || !m.runtime().equals(runtime)) {
      return;
    }
    if (owner().kernel.listening()) {
      owner().kernel.tell(new ReflectionEvent.MetaLost(owner().name(), runtime, message));
    }
    LockStepGate g = gate;
    if (g != null) {
      g.release("its meta's " + message);
    }
  }

  /** In lock step: tells the meta that every notification up to now has been sent. */
  private void sendBarrier(long n) {
    Address m = metaAddress;
    LockStepGate g = gate;
    if (g == null || !lockStepping || m == null) {
      return;
    }
    ActiveObject<LockStepDesk> desk = owner().kernel.lockStepDesk();
    if (!gateRegistered) {
      desk.send(d -> d.register(owner().address(), g));
      gateRegistered = true;
    }
    g.sent(n);
    send(m, new Wire.Barrier(owner().address(), m, n, seq, now(), desk.address()));
  }

  /** Sends {@code event} to the meta at {@code m}, of this runtime or another. */
  private void send(Address m, Event event) {
    BehavioralMetaImpl local = meta;
    try {
      if (local != null && local.address().equals(m)) {
        local.object().send(event);
      } else {
        owner().kernel.runtime().ref(m).send(event);
      }
    } catch (ObjectStoppedException e) {
      LOG.debug("{} not delivered: its meta is stopped", event);
    }
  }

  /** The first event of an instant is where a BEGIN_OF_CYCLE entity applies its adaptations. */
  private void beginInstant() {
    if (!instantBegun) {
      instantBegun = true;
      if (adaptationPoint == AdaptationPoint.BEGIN_OF_CYCLE && program == null) {
        applyPending();
      }
    }
  }

  private static final Comparator<AdaptationRequest> BY_VERSION =
      Comparator.comparingLong(AdaptationRequest::version);

  /**
   * The adaptation point: applies the pending requests in version order, timed by the kernel's
   * stopwatch against the clock's period (the cycle's time budget).
   */
  private void applyPending() {
    if (pending.isEmpty()) {
      return;
    }
    if (pending.size() > 1) {
      List<AdaptationRequest> sorted = new ArrayList<>(pending);
      sorted.sort(BY_VERSION);
      pending.clear();
      pending.addAll(sorted);
    }
    TimeSource stopwatch = owner().kernel.options().stopwatch();
    long start = stopwatch.nanoTime();
    long before = start;
    boolean overrun = false;
    AdaptationRequest r;
    while ((r = pending.poll()) != null) {
      String refusal = adapt(r);
      long after = stopwatch.nanoTime();
      overrun |= after - start > budgetNanos;
      if (owner().kernel.listening()) {
        owner()
            .kernel
            .tell(
                new ReflectionEvent.Applied(
                    owner().name(), instant, r, refusal, after - before, overrun));
      }
      before = after;
    }
    long spent = before - start;
    if (spent > adaptationMaxNanos) {
      adaptationMaxNanos = spent;
    }
    if (overrun) {
      adaptationOverruns++;
    }
  }

  /** Applies the behavior named {@code behavior}: {@link Entity#call}. */
  @Nullable Object call(String behavior, @Nullable Object input) {
    beginInstant();
    Step<E> step = activation.apply(behavior, input);
    stepped(step, input);
    return step.result();
  }

  /** Flow 5: the structural meta's behaviors replace this entity's; its program is told. */
  void harmonize(Behaviors<E> behaviors) {
    activation.harmonize(behaviors);
    if (program != null) {
      program.harmonized(behaviors);
    }
  }

  /** A behavioral meta takes this entity: it is told everything from a complete state on. */
  void attach(BehavioralMetaImpl next) {
    meta = next;
    metaAddress = next.address();
    sendBarrier(instant);
    snapshot();
  }

  /**
   * A behavioral meta of another runtime takes this entity; a previous meta of this runtime lets it
   * go (one of another runtime is not told: its model goes stale).
   */
  private void attachRemote(Address next) {
    BehavioralMetaImpl previous = meta;
    meta = null;
    metaAddress = next;
    if (previous != null) {
      previous.deleteBaseLevelEntity(owner());
    }
    sendBarrier(instant);
    snapshot();
  }

  /** A behavioral meta lets go of this entity. */
  void detach(BehavioralMetaImpl previous) {
    if (meta == previous) {
      meta = null;
      metaAddress = null;
    }
  }

  /**
   * A failure of this entity's object (docs/architecture.md, runtime semantics 8), on the object's
   * thread.
   */
  void failed(@Nullable Event event, Throwable error) {
    Address m = metaAddress;
    if (m != null) {
      notify(
          m,
          new FailureEvent(
              owner().address(),
              m,
              ++seq,
              now(),
              error.getClass().getName(),
              error.getMessage() == null ? "" : error.getMessage(),
              event == null ? "" : event.toString()));
    }
  }

  /** Applies {@code r}, or refuses it; acknowledges it either way. Answers the refusal or null. */
  private @Nullable String adapt(AdaptationRequest r) {
    if (r.version() <= appliedVersion) {
      String refusal =
          "version " + r.version() + " is not after the applied version " + appliedVersion;
      ack(r, refusal);
      return refusal;
    }
    try {
      if (program != null) {
        program.adapt(r.adaptation());
      }
      switch (r.adaptation()) {
        case Adaptation.SetNotification s -> {
          policy = s.policy();
          lastObserved = null;
          if (s.policy().states()) {
            snapshot();
          }
        }
        case Adaptation.ApplyBehavior a ->
            stepped(activation.apply(a.behavior(), a.input()), a.input());
      }
    } catch (RuntimeException e) {
      ack(r, e.toString());
      return e.toString();
    }
    appliedVersion = r.version();
    ack(r, null);
    return null;
  }

  private void ack(AdaptationRequest r, @Nullable String failure) {
    AdaptationAck ack =
        new AdaptationAck(r.destination(), r.sender(), r.version(), failure == null, failure);
    try {
      owner().kernel.runtime().ref(r.sender()).send(ack);
    } catch (ObjectStoppedException e) {
      LOG.debug("adaptation ack {} not delivered: its meta is stopped", ack);
    }
  }

  private void snapshot() {
    current = activation.state();
    Address m = metaAddress;
    if (m != null) {
      Map<String, Object> all = current.observe();
      lastObserved = project(grain(current, all, policy), policy);
      notify(m, new StateEvent(owner().address(), m, ++seq, now(), null, all, true));
    }
  }

  private void stepped(Step<E> step, @Nullable Object input) {
    current = step.after();
    NotificationPolicy p = policy;
    Address m = metaAddress;
    Map<String, Object> observed = step.after().observe();
    Map<String, Object> grained = grain(step.after(), observed, p);
    if (m != null
        && p.actions()
        && (p.behaviors().isEmpty() || p.behaviors().contains(step.behavior()))) {
      notify(m, new ActionEvent(owner().address(), m, ++seq, now(), step.behavior(), input));
    }
    if (m != null && p.states()) {
      Map<String, Object> projected = project(grained, p);
      if (!projected.equals(lastObserved)) {
        lastObserved = projected;
        boolean complete = projected.equals(observed);
        notify(
            m,
            new StateEvent(
                owner().address(), m, ++seq, now(), step.behavior(), projected, complete));
      }
    }
    thresholds(m, p.thresholds(), observed);
    if (m != null && step.result() instanceof Reflect r) {
      notify(
          m, new ReflectiveRequest(owner().address(), m, ++seq, now(), r.subject(), r.argument()));
    }
  }

  private void thresholds(
      @Nullable Address m, List<Threshold> watched, Map<String, Object> observed) {
    for (Threshold t : watched) {
      if (!(observed.get(t.property()) instanceof Number n)) {
        continue;
      }
      double v = n.doubleValue();
      Boolean was = below.get(t.name());
      Boolean now = v < t.low() ? Boolean.TRUE : v > t.high() ? Boolean.FALSE : was;
      if (now == null) {
        continue;
      }
      below.put(t.name(), now);
      if (was != null && !was.equals(now) && m != null) {
        notify(
            m,
            new ThresholdEvent(owner().address(), m, ++seq, now(), t.name(), t.property(), v, now));
      }
    }
  }

  /** A statechart observed at a coarse depth; anything else as it observes itself. */
  private Map<String, Object> grain(E state, Map<String, Object> observed, NotificationPolicy p) {
    if (p.depth() > 0
        && activation.space() instanceof Statechart chart
        && state instanceof Configuration c) {
      return chart.observe(c, p.depth());
    }
    return observed;
  }

  private static Map<String, Object> project(Map<String, Object> observed, NotificationPolicy p) {
    if (p.observed().isEmpty()) {
      return observed;
    }
    Map<String, Object> m = new LinkedHashMap<>();
    for (var e : observed.entrySet()) {
      if (p.observed().contains(e.getKey())) {
        m.put(e.getKey(), e.getValue());
      }
    }
    return m;
  }

  /**
   * Numbers the next {@code n} notifications but does not send them: a loss in transit, which the
   * in-JVM transport never causes, for the tests of resynchronization.
   */
  void loseNotifications(int n) {
    toLose = n;
  }

  private void notify(Address m, Notification n) {
    if (owner().kernel.listening()) {
      owner().kernel.tell(new ReflectionEvent.Notified(owner().name(), instant, n));
    }
    if (toLose > 0) {
      toLose--;
      return;
    }
    BehavioralMetaImpl local = meta;
    try {
      if (local != null && local.address().equals(m)) {
        local.object().send(n);
      } else {
        owner().kernel.runtime().ref(m).send(n);
      }
    } catch (ObjectStoppedException e) {
      LOG.debug("notification {} not delivered: its meta is stopped", n);
    }
  }

  /** The entity's time now, from its kernel's time source: what its notifications carry. */
  private long now() {
    return owner().kernel.nanoTime();
  }

  /** What the program sees of its instant; used only on the entity's object. */
  private final class Instant implements InstantContext {
    @Override
    public long instant() {
      return instant;
    }

    @Override
    public Entity self() {
      return owner();
    }

    @Override
    public List<Stimulus> stimuli() {
      return List.copyOf(stimuli);
    }

    @Override
    public State state() {
      return activation.state();
    }

    @Override
    public @Nullable Object apply(String behavior, @Nullable Object input) {
      requireNonNull(behavior, "behavior");
      Step<E> step = activation.apply(behavior, input);
      stepped(step, input);
      return step.result();
    }
  }
}

package org.armgals.active;

import static java.util.Objects.requireNonNull;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import org.jspecify.annotations.Nullable;

/**
 * An active object: its servant, its bounded buffer, its scheduling state. The one class behind
 * {@link ActiveObject} and the local {@link ActiveRef}.
 *
 * <p><b>Buffer.</b> Producers append with one atomic exchange on {@link #tail} (a Vyukov
 * multi-producer single-consumer linked queue whose nodes are the envelopes themselves); the
 * object's activation is the single consumer and owns {@link #head} and the private list of
 * deferred events, those it found not processable. {@link #size} counts both and is the capacity
 * check. An object whose policy is drop-oldest uses a {@link LockedBuffer} instead, since a
 * producer must then remove the oldest event.
 *
 * <p><b>Scheduling.</b> {@link #state} holds {@link #SCHEDULED} while the object is in its
 * runtime's run queue or being run, so at most one thread consumes at a time; {@link #STOPPED} once
 * stopped. A producer that finds an asynchronous object idle schedules it. An activation processes
 * up to {@link #BATCH} events, then goes back to the run queue or, with nothing processable left,
 * idles (re-checking the buffer after clearing the flag so no wake-up is lost). A synchronous
 * object is scheduled only by its clock, once per instant.
 */
final class Core<S> extends SenderSidePadding implements ActiveObject<S> {
  static final int SCHEDULED = 1;
  static final int STOPPED = 2;
  static final int BATCH = 256;

  /** How long, in spins, an activation waits for more events before going idle. */
  static final int LINGER_SPINS = 200;

  private static final VarHandle TAIL;
  private static final VarHandle SIZE;
  private static final VarHandle STATE;
  private static final VarHandle BLOCKED;
  private static final ThreadLocal<@Nullable Core<?>> CURRENT = new ThreadLocal<>();

  static {
    try {
      MethodHandles.Lookup l = MethodHandles.lookup();
      TAIL = l.findVarHandle(SenderSide.class, "tail", Envelope.class);
      SIZE = l.findVarHandle(SenderSide.class, "size", int.class);
      STATE = l.findVarHandle(Core.class, "state", int.class);
      BLOCKED =
          l.findVarHandle(
              SenderSidePadding.class, "blocked", java.util.concurrent.ConcurrentLinkedQueue.class);
    } catch (ReflectiveOperationException e) {
      throw new ExceptionInInitializerError(e);
    }
  }

  final RuntimeImpl runtime;
  private final S servant;
  private final ObjectConfig config;
  private final @Nullable LockedBuffer locked;

  private volatile int state;

  // consumer only
  private Envelope head;
  private @Nullable Envelope deferredHead;
  private boolean dirty;

  /** The envelope whose guard threw, and what it threw: it fails instead of running. */
  private @Nullable GuardFailure guardFailure;

  private record GuardFailure(Envelope envelope, Throwable error) {}

  private int taken;

  /** Written by this object's own thread only: numbers what it sends. */
  private long sendSeq;

  /** The state of a synchronous object between its clock's two release phases. */
  static final class Instant {
    /** The last event linked at the last release: the instant takes it and all before it. */
    @Nullable Envelope releasedTail;

    /** The instant to run, or last run. */
    long number;

    /** Counted down when the object can be released again. */
    @Nullable CountDownLatch done;
  }

  /** The first node of an empty buffer: it carries no event. */
  private static final class Stub extends Envelope {
    @Override
    boolean processable(Object servant) {
      return false;
    }

    @Override
    void process(Core<?> receiver) {
      throw new IllegalStateException("the buffer's stub is never processed");
    }
  }

  Core(RuntimeImpl runtime, long id, S servant, ObjectConfig config) {
    super(id, config.mode() == Mode.SYNCHRONOUS ? new Instant() : null);
    this.runtime = runtime;
    this.servant = servant;
    this.config = config;
    this.locked =
        config.overflow() instanceof OverflowPolicy.DropOldest ? new LockedBuffer() : null;
    Envelope stub = new Stub();
    this.head = stub;
    this.tail = stub;
  }

  /** The instant a synchronous object is running or last ran; 0 before its first. */
  long currentInstant() {
    Instant i = instant;
    return i == null ? 0 : i.number;
  }

  static @Nullable Core<?> current() {
    return CURRENT.get();
  }

  S servant() {
    return servant;
  }

  // ---------------------------------------------------------------- ActiveObject / ActiveRef

  @Override
  public Address address() {
    Address a = address;
    if (a == null) {
      a = new Address(runtime.name(), id);
      address = a;
    }
    return a;
  }

  @Override
  public Mode mode() {
    return config.mode();
  }

  @Override
  public ObjectConfig config() {
    return config;
  }

  @Override
  public int queueDepth() {
    LockedBuffer lb = locked;
    return lb != null ? lb.size() : size;
  }

  @Override
  public boolean isStopped() {
    return (state & STOPPED) != 0;
  }

  @Override
  public void send(Event event) {
    requireNonNull(event, "event");
    if (event instanceof Envelope e && !(event instanceof Requests.FutureReply)) {
      post(e);
    } else {
      if (!(event instanceof Callable<?, ?>) && !address().equals(event.destination())) {
        throw new IllegalArgumentException(
            "event " + event + " is addressed to " + event.destination() + ", not " + address());
      }
      post(new Requests.Wrapped(event));
    }
  }

  @Override
  public void send(ServantAction<? super S> action) {
    post(new Requests.Action<S>(requireNonNull(action, "action"), null));
  }

  @Override
  public void sendWhen(Guard<? super S> guard, ServantAction<? super S> action) {
    post(new Requests.Action<S>(requireNonNull(action, "action"), requireNonNull(guard, "guard")));
  }

  @Override
  public <R extends @Nullable Object> FutureValue<R> call(ServantFunction<? super S, R> function) {
    requireNonNull(function, "function");
    return request(function, null);
  }

  @Override
  public <R extends @Nullable Object> FutureValue<R> callWhen(
      Guard<? super S> guard, ServantFunction<? super S, R> function) {
    requireNonNull(function, "function");
    requireNonNull(guard, "guard");
    return request(function, guard);
  }

  @Override
  public Future signal(ServantAction<? super S> action) {
    requireNonNull(action, "action");
    return request(
        s -> {
          action.run(s);
          return null;
        },
        null);
  }

  @Override
  public <R extends @Nullable Object> FutureValue<R> call(
      SynchronizedMethodRequest<? super S, R> request) {
    requireNonNull(request, "request");
    ReplyFuture<R> f = newFuture();
    request.reply(f);
    post(request);
    return f;
  }

  @Override
  public <I> I proxy(Class<I> type) {
    return Proxies.create(this, servant, type);
  }

  @Override
  public void stop() {
    for (; ; ) {
      int s = state;
      if ((s & STOPPED) != 0) {
        return;
      }
      if (STATE.compareAndSet(this, s, s | STOPPED)) {
        break;
      }
    }
    runtime.unregister(this);
    if (config.clock() instanceof ClockSupport.Owner owner) {
      owner.support().unregister(this);
    }
    roomMade(); // senders blocked by a full buffer learn at once that the object is gone
    trySchedule();
  }

  @Override
  public String toString() {
    return "ActiveObject[" + address() + ", " + config.mode() + ", " + servant + "]";
  }

  // ---------------------------------------------------------------- sending

  private <R extends @Nullable Object> FutureValue<R> request(
      ServantFunction<? super S, R> function, @Nullable Guard<? super S> guard) {
    ReplyFuture<R> f = newFuture();
    post(new Requests.Function<S, R>(function, guard, f));
    return f;
  }

  /**
   * Queues a synchronized request whose outcome goes to {@code reply} instead of a future the
   * runtime makes (a request from another runtime, answered over its transport). Any thread.
   */
  <R extends @Nullable Object> void request(
      ServantFunction<? super S, R> function, Guard<? super S> guard, Reply<R> reply) {
    post(new Requests.Function<S, R>(function, guard, reply));
  }

  private <R extends @Nullable Object> ReplyFuture<R> newFuture() {
    Core<?> sender = CURRENT.get();
    if (sender != null && sender.config.mode() == Mode.SYNCHRONOUS) {
      return new SyncFuture<>(sender, address(), sender.sendSeq + 1);
    }
    return new ValueFuture<>(this);
  }

  /** Routes an envelope from the calling thread's object (if any) to this object. */
  void post(Envelope e) {
    Core<?> sender = CURRENT.get();
    Address from = null;
    long seq = 0;
    if (sender != null) {
      from = sender.address();
      seq = ++sender.sendSeq;
    }
    if (!e.bind(from, this, seq)) {
      throw new IllegalArgumentException("this request was already sent once: " + e);
    }
    enqueue(e);
  }

  /** Queues a routed envelope, applying the overflow policy. Any thread. */
  void enqueue(Envelope e) {
    if ((state & STOPPED) != 0) {
      runtime.countRejected();
      throw new ObjectStoppedException(address());
    }
    LockedBuffer lb = locked;
    if (lb != null) {
      Envelope dropped = lb.offer(e, config.capacity());
      if (dropped != null) {
        reportDrop(dropped);
      }
    } else {
      if (!e.privileged() && !reserve(e)) {
        return;
      }
      if (e.privileged()) {
        SIZE.getAndAdd(this, 1);
      }
      Envelope prev = (Envelope) TAIL.getAndSet(this, e);
      prev.setNext(e);
    }
    if (config.mode() == Mode.ASYNCHRONOUS || (state & STOPPED) != 0) {
      if ((state & SCHEDULED) == 0) {
        trySchedule();
      }
    }
  }

  /** Takes one place in the buffer; false if the event was dropped. Throws if refused. */
  private boolean reserve(Envelope e) {
    int capacity = config.capacity();
    long deadline = 0;
    boolean waited = false;
    for (; ; ) {
      if ((int) SIZE.getAndAdd(this, 1) < capacity) {
        return true;
      }
      // Over: give the place back. Another sender may have seen the transient excess and be
      // about to park; wake it if there is room after all.
      if ((int) SIZE.getAndAdd(this, -1) - 1 < capacity) {
        roomMade();
      }
      switch (config.overflow()) {
        case OverflowPolicy.Reject r -> {
          runtime.countRejected();
          throw new BufferFullException(address(), capacity, "policy reject");
        }
        case OverflowPolicy.DropNewest d -> {
          reportDrop(e);
          return false;
        }
        case OverflowPolicy.Block b -> {
          if (!waited) {
            deadline = runtime.timeSource().nanoTime() + b.timeout().toNanos();
            waited = true;
          }
          if (!awaitRoom(deadline)) {
            runtime.countRejected();
            throw new BufferFullException(
                address(), capacity, "sender blocked for " + b.timeout() + " without room");
          }
          if ((state & STOPPED) != 0) {
            runtime.countRejected();
            throw new ObjectStoppedException(address());
          }
        }
        case OverflowPolicy.DropOldest d ->
            throw new AssertionError("drop-oldest uses LockedBuffer");
      }
    }
  }

  private void reportDrop(Envelope e) {
    runtime.countDropped();
    e.abandon(new BufferFullException(address(), config.capacity(), "event dropped: " + e));
    try {
      config.listener().onDropped(address(), e.event(), config.overflow());
    } catch (RuntimeException t) {
      runtime.reportFailure(this, e.event(), t);
    }
  }

  private void trySchedule() {
    for (; ; ) {
      int s = state;
      if ((s & SCHEDULED) != 0) {
        return;
      }
      if (STATE.compareAndSet(this, s, s | SCHEDULED)) {
        runtime.dispatcher().schedule(this);
        return;
      }
    }
  }

  // ---------------------------------------------------------------- consuming

  /** One activation, on a worker thread: the object holds {@link #SCHEDULED}. */
  void run() {
    CURRENT.set(this);
    int processed = 0;
    boolean more = false;
    CountDownLatch released = null;
    try {
      if ((state & STOPPED) != 0) {
        cancelQueued();
      } else if (config.mode() == Mode.SYNCHRONOUS) {
        Instant i = java.util.Objects.requireNonNull(instant);
        released = i.done;
        i.done = null;
        processed = runInstant();
      } else {
        int linger = LINGER_SPINS;
        while (processed < BATCH && (state & STOPPED) == 0) {
          Envelope e = takeProcessable();
          if (e == null) {
            linger = lingerForEvents(linger);
            if (linger < 0) {
              break;
            }
            continue;
          }
          processOne(e);
          processed++;
        }
        more = processed == BATCH;
      }
    } finally {
      returnTaken();
      CURRENT.remove();
      runtime.countProcessed(processed);
      if (more) {
        runtime.dispatcher().requeue(this); // fairness: the back of the shared queue
      } else {
        roomMade();
        STATE.getAndBitwiseAnd(this, ~SCHEDULED);
      }
      // The instant ends only once the object can be released again.
      if (released != null) {
        released.countDown();
      }
    }
    if (!more && needsActivation()) {
      trySchedule();
    }
  }

  /**
   * Out of events: waits a little for more before going idle, if no other object is waiting for a
   * worker. A sender streaming to this object then costs no scheduling round trip per few events.
   *
   * @return the spins left, or -1 to go idle
   */
  private int lingerForEvents(int spins) {
    returnTaken(); // while it lingers, the object's count of queued events is exact
    LockedBuffer lb = locked;
    while (spins > 0 && runtime.dispatcher().nothingWaiting()) {
      spins--;
      Thread.onSpinWait();
      if (lb != null ? lb.hasUnseen() : head.next() != null) {
        return spins;
      }
    }
    return -1;
  }

  /** After an activation: is there something the idle object must still do? */
  private boolean needsActivation() {
    boolean stopped = (state & STOPPED) != 0;
    if (stopped) {
      return queueDepth() > 0;
    }
    if (config.mode() == Mode.SYNCHRONOUS) {
      return false;
    }
    LockedBuffer lb = locked;
    return lb != null ? lb.hasUnseen() : tail != head;
  }

  /**
   * Counts an event taken out of the buffer. Places go back to the senders in batches of {@link
   * #takenBatch()} (at most 1/64 of the capacity, 1 for buffers under 128): one contended atomic
   * per batch rather than per event. Every batch is returned before the object parks or goes idle.
   */
  private int takenBatch() {
    return Math.max(1, Math.min(64, config.capacity() >> 6));
  }

  private void taken() {
    if (locked == null && ++taken >= takenBatch()) {
      returnTaken();
    }
  }

  /** Returns the places of the events taken so far. Consumer only. */
  void returnTaken() {
    int t = taken;
    if (t == 0) {
      return;
    }
    taken = 0;
    int left = (int) SIZE.getAndAdd(this, -t) - t;
    // Wake blocked senders at half capacity, not for every place: a park and an unpark per event
    // would make a full buffer far slower than a half-empty one.
    if (left <= config.capacity() >> 1) {
      roomMade();
    }
  }

  private void processOne(Envelope e) {
    taken();
    try {
      GuardFailure g = guardFailure;
      if (g != null && g.envelope() == e) {
        guardFailure = null;
        throw new IllegalStateException("the guard of " + e + " threw " + g.error(), g.error());
      }
      e.process(this);
    } catch (Throwable t) {
      ActiveRuntimeErrors.throwIfFatal(t);
      e.failed(t);
      runtime.reportFailure(this, e.event(), t);
    } finally {
      dirty = true;
      e.clear();
    }
  }

  /** The oldest processable event, or null if none; consumer only. */
  private @Nullable Envelope takeProcessable() {
    LockedBuffer lb = locked;
    if (lb != null) {
      Envelope e = lb.takeProcessable(this, dirty);
      dirty = false;
      return e;
    }
    if (deferredHead != null && dirty) {
      dirty = false;
      Envelope prev = null;
      for (Envelope d = deferredHead; d != null; prev = d, d = d.deferredNext) {
        if (processableSafely(d)) {
          unlinkDeferred(prev, d);
          return d;
        }
      }
    }
    dirty = false;
    for (; ; ) {
      Envelope e = pollInbox();
      if (e == null) {
        return null;
      }
      if (processableSafely(e)) {
        return e;
      }
      appendDeferred(e);
    }
  }

  boolean processableSafely(Envelope e) {
    try {
      return e.processable(servant);
    } catch (Throwable t) {
      ActiveRuntimeErrors.throwIfFatal(t);
      // A guard that throws makes its event fail (without running) rather than block the buffer.
      guardFailure = new GuardFailure(e, t);
      return true;
    }
  }

  /**
   * The next linked event, or null. It does not read {@link #tail}: that line is written by every
   * send, and a consumer reading it per event makes it bounce between cores. An event whose sender
   * has swapped the tail but not linked it yet is seen on a later poll (the end-of-activation check
   * reads the tail, so it is never lost).
   */
  private @Nullable Envelope pollInbox() {
    Envelope n = head.next();
    if (n != null) {
      head = n;
    }
    return n;
  }

  /** As {@link #pollInbox()}, but waits for a link in progress (all events up to the tail). */
  private @Nullable Envelope pollInboxToTail() {
    Envelope h = head;
    Envelope n = h.next();
    if (n == null) {
      if (h == tail) {
        return null;
      }
      while ((n = h.next()) == null) {
        Thread.onSpinWait();
      }
    }
    head = n;
    return n;
  }

  private void appendDeferred(Envelope e) {
    e.deferredNext = null;
    if (deferredTail == null) {
      deferredHead = e;
    } else {
      deferredTail.deferredNext = e;
    }
    deferredTail = e;
  }

  private void unlinkDeferred(@Nullable Envelope prev, Envelope d) {
    Envelope next = d.deferredNext;
    if (prev == null) {
      deferredHead = next;
    } else {
      prev.deferredNext = next;
    }
    if (deferredTail == d) {
      deferredTail = prev;
    }
    d.deferredNext = null;
  }

  /** Stopped: discard everything queued, failing the futures. */
  private void cancelQueued() {
    ObjectStoppedException stopped = new ObjectStoppedException(address());
    List<Envelope> all = new ArrayList<>();
    LockedBuffer lb = locked;
    if (lb != null) {
      lb.drainTo(all);
    } else {
      takeDeferred(all);
      for (Envelope e = pollInboxToTail(); e != null; e = pollInboxToTail()) {
        all.add(e);
      }
    }
    if (lb == null) {
      SIZE.getAndAdd(this, -all.size());
    }
    for (Envelope e : all) {
      e.abandon(stopped);
      e.clear();
    }
    roomMade();
  }

  /** Moves the deferred events, oldest first, into {@code into}; the deferred list is empty. */
  private void takeDeferred(List<Envelope> into) {
    for (Envelope d = deferredHead; d != null; d = d.deferredNext) {
      into.add(d);
    }
    deferredHead = null;
    deferredTail = null;
  }

  // ---------------------------------------------------------------- blocked senders

  /** Parks the sender until there may be room, the object stopped, or the deadline passed. */
  private boolean awaitRoom(long deadline) {
    Core<?> sender = CURRENT.get();
    if (sender != null) {
      sender.returnTaken();
    }
    var q = blocked;
    if (q == null) {
      BLOCKED.compareAndSet(this, null, new java.util.concurrent.ConcurrentLinkedQueue<Thread>());
      q = blocked;
    }
    Thread me = Thread.currentThread();
    q.add(me);
    Dispatcher.beforeBlock();
    try {
      for (; ; ) {
        if (size < config.capacity() || (state & STOPPED) != 0) {
          return true;
        }
        long remaining = deadline - runtime.timeSource().nanoTime();
        if (remaining <= 0) {
          return false;
        }
        java.util.concurrent.locks.LockSupport.parkNanos(this, remaining);
        if (Thread.interrupted()) {
          me.interrupt();
          runtime.countRejected();
          throw new ActiveException(
              "interrupted while waiting for room in the buffer of " + address());
        }
      }
    } finally {
      q.remove(me);
      Dispatcher.afterBlock();
    }
  }

  /** Wakes the blocked senders, if any, after the buffer made room. */
  private void roomMade() {
    var q = blocked;
    if (q != null) {
      for (Thread t : q) {
        java.util.concurrent.locks.LockSupport.unpark(t);
      }
    }
  }

  // ---------------------------------------------------------------- synchronous mode

  /** Clock, phase 1 of a release: fixes which events belong to this instant. */
  void beginInstant() {
    LockedBuffer lb = locked;
    if (lb != null) {
      lb.markRelease();
    } else {
      // The last node linked now: events whose place was reserved but that are not linked yet
      // were sent at the same time as the release, and belong to the next instant.
      java.util.Objects.requireNonNull(instant).releasedTail = tail;
    }
  }

  /** Clock, phase 2: runs the instant on a worker; false if the object is stopped or busy. */
  boolean scheduleInstant(long instant, CountDownLatch done) {
    for (; ; ) {
      int s = state;
      if (s != 0) {
        return false;
      }
      if (STATE.compareAndSet(this, 0, SCHEDULED)) {
        Instant i = java.util.Objects.requireNonNull(this.instant);
        i.number = instant;
        i.done = done;
        runtime.dispatcher().schedule(this);
        return true;
      }
    }
  }

  private static final Comparator<Envelope> INSTANT_ORDER =
      Comparator.comparing((Envelope e) -> e.from == null ? "" : e.from.runtime())
          .thenComparingLong(e -> e.from == null ? 0 : e.from.id())
          .thenComparingLong(e -> e.seq);

  /** Retries skipped events oldest first, restarting after each one processed. */
  private int retrySkipped(List<Envelope> skipped) {
    int processed = 0;
    boolean progress = true;
    while (progress && (state & STOPPED) == 0) {
      progress = false;
      for (int i = 0; i < skipped.size(); i++) {
        Envelope e = skipped.get(i);
        if (processableSafely(e)) {
          skipped.remove(i);
          processOne(e);
          processed++;
          progress = true;
          break;
        }
      }
    }
    return processed;
  }

  /** Takes every event waiting at the release, in a deterministic order, then the cycle. */
  private int runInstant() {
    List<Envelope> batch = new ArrayList<>();
    LockedBuffer lb = locked;
    if (lb != null) {
      lb.takeReleased(batch);
    } else {
      takeDeferred(batch);
      Envelope last = java.util.Objects.requireNonNull(instant).releasedTail;
      if (last != null && last != head) {
        for (Envelope e = pollInboxToTail(); e != null; e = pollInboxToTail()) {
          batch.add(e);
          if (e == last) {
            break;
          }
        }
      }
    }
    batch.sort(INSTANT_ORDER);
    int processed = processInstant(batch, lb);
    if (servant instanceof ReactiveCycle rc && (state & STOPPED) == 0) {
      try {
        rc.onCycle(java.util.Objects.requireNonNull(instant).number);
      } catch (Throwable t) {
        ActiveRuntimeErrors.throwIfFatal(t);
        runtime.reportFailure(this, null, t);
      }
    }
    return processed;
  }

  /**
   * Processes an instant's events in order with the asynchronous rule: after each processed event
   * (a state change) the events skipped so far are retried, oldest first, before newer ones. What
   * stays unprocessable waits for a later instant.
   */
  private int processInstant(List<Envelope> batch, @Nullable LockedBuffer lb) {
    int processed = 0;
    List<Envelope> skipped = new ArrayList<>();
    for (int i = 0; i < batch.size(); i++) {
      Envelope e = batch.get(i);
      if ((state & STOPPED) != 0) {
        // Stopped by one of the instant's events: the rest is discarded with the buffer.
        skipped.addAll(batch.subList(i, batch.size()));
        break;
      }
      if (!processableSafely(e)) {
        skipped.add(e);
        continue;
      }
      processOne(e);
      processed++;
      processed += retrySkipped(skipped);
    }
    if (lb != null) {
      lb.putBack(skipped);
    } else {
      for (Envelope e : skipped) {
        appendDeferred(e);
      }
    }
    return processed;
  }
}

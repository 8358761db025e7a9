package org.armgals.active;

import static java.util.Objects.requireNonNull;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Iterator;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CountDownLatch;
import org.jspecify.annotations.Nullable;

/**
 * An active object: its servant, its bounded buffer, its scheduling state. The one class behind
 * {@link ActiveObject} and the local {@link ActiveRef}.
 *
 * <p><b>Buffer.</b> Producers append with one atomic exchange on {@link #tail} (a Vyukov
 * multi-producer single-consumer linked queue whose nodes are the envelopes themselves); the
 * object's activation is the single consumer and owns {@link #head} (held in its carrier while it
 * runs, so that taking an event writes nothing in the object) and the private list of deferred
 * events, those it found not processable. {@link #size} counts both and is the capacity check. An
 * object whose policy is drop-oldest uses a {@link LockedBuffer} instead, since a producer must
 * then remove the oldest event.
 *
 * <p><b>Scheduling.</b> {@link #state} holds {@link #SCHEDULED} while the object is in its
 * runtime's run queue or being run, so at most one thread consumes at a time; {@link #STOPPED} once
 * stopped. A producer that finds an asynchronous object idle schedules it. An activation processes
 * up to {@link #BATCH} events, then goes back to the run queue or, with nothing processable left,
 * idles (re-checking the buffer after clearing the flag so no wake-up is lost). A synchronous
 * object is scheduled only by its clock, once per instant.
 */
final class Core<S> extends SenderSide implements ActiveObject<S> {
  static final int SCHEDULED = 1;
  static final int STOPPED = 2;
  static final int BATCH = 256;

  /** How long, in spins, an activation waits for more events before going idle. */
  static final int LINGER_SPINS = 200;

  /** The longest interval, in spins, between two looks at the buffer while lingering. */
  static final int LINGER_MAX_INTERVAL = 64;

  private static final VarHandle TAIL;
  private static final VarHandle SIZE;
  private static final VarHandle STATE;
  private static final VarHandle RARE;
  private static final VarHandle STOPPED_COPY;

  static {
    try {
      MethodHandles.Lookup l = MethodHandles.lookup();
      TAIL = l.findVarHandle(SenderSide.class, "tail", Link.class);
      SIZE = l.findVarHandle(SenderSide.class, "size", int.class);
      STATE = l.findVarHandle(SenderSide.class, "state", int.class);
      RARE = l.findVarHandle(ReceiverSide.class, "rare", Rare.class);
      STOPPED_COPY = l.findVarHandle(ReceiverSide.class, "stopped", boolean.class);
    } catch (ReflectiveOperationException e) {
      throw new ExceptionInInitializerError(e);
    }
  }

  private record GuardFailure(Envelope envelope, Throwable error) {}

  /** The state of a synchronous object between its clock's two release phases. */
  static final class Instant {
    /** The last node linked at the last release: the instant takes it and all before it. */
    @Nullable Link releasedTail;

    /** The instant to run, or last run. */
    long number;

    /** Counted down when the object can be released again. */
    @Nullable CountDownLatch done;

    /**
     * Written by this object's own thread only: numbers what it sends, so that a reply names the
     * request it answers.
     */
    long sendSeq;
  }

  /**
   * What few objects need, apart from the fields every object has (an idle object costs at most 100
   * bytes: decision 0045). Made with the object for synchronous and drop-oldest objects, on first
   * need for the others.
   */
  static final class Rare {
    /** Synchronous mode only: what the clock's release fixed. */
    final @Nullable Instant instant;

    /** The drop-oldest policy only: the buffer, under a lock. */
    final @Nullable LockedBuffer locked;

    /** Senders parked by the block policy. */
    final ConcurrentLinkedQueue<Thread> blocked = new ConcurrentLinkedQueue<>();

    /** The future this object's thread waits on, for wait-for cycle detection. */
    volatile @Nullable ValueFuture<?> waitingFor;

    // consumer only

    /** The events found not processable, oldest first; null until the first. */
    @Nullable ArrayDeque<Envelope> deferred;

    /** Whether an event was processed since the deferred events were last tried. */
    boolean dirty;

    /** The envelope whose guard threw, and what it threw: it fails instead of running. */
    @Nullable GuardFailure guardFailure;

    Rare(@Nullable Instant instant, @Nullable LockedBuffer locked) {
      this.instant = instant;
      this.locked = locked;
    }
  }

  Core(RuntimeImpl runtime, long id, S servant, ObjectConfig config) {
    super(servant, runtime, id, config);
    boolean sync = config.mode() == Mode.SYNCHRONOUS;
    boolean dropOldest = config.overflow() instanceof OverflowPolicy.DropOldest;
    if (sync || dropOldest) {
      this.rare = new Rare(sync ? new Instant() : null, dropOldest ? new LockedBuffer() : null);
    }
    // A plain write: the object is published safely (by the object table's release store), and a
    // volatile one would cost a fence per object created.
    TAIL.set(this, this);
  }

  /** This object's rare fields, made on first need. Any thread. */
  Rare rare() {
    Rare r = rare;
    if (r == null) {
      RARE.compareAndSet(this, null, new Rare(null, null));
      r = requireNonNull(rare);
    }
    return r;
  }

  private @Nullable LockedBuffer locked() {
    Rare r = rare;
    return r == null ? null : r.locked;
  }

  private @Nullable Instant instant() {
    Rare r = rare;
    return r == null ? null : r.instant;
  }

  /** The future this object's thread waits on, or null. */
  @Nullable ValueFuture<?> waitingFor() {
    Rare r = rare;
    return r == null ? null : r.waitingFor;
  }

  /** Records the future this object's thread waits on (null: none). Its own thread only. */
  void waitingFor(@Nullable ValueFuture<?> future) {
    if (future != null) {
      rare().waitingFor = future;
    } else {
      Rare r = rare;
      if (r != null) {
        r.waitingFor = null;
      }
    }
  }

  /** The instant a synchronous object is running or last ran; 0 before its first. */
  long currentInstant() {
    Instant i = instant();
    return i == null ? 0 : i.number;
  }

  static @Nullable Core<?> current() {
    return Carrier.running();
  }

  @SuppressWarnings("unchecked") // spawned with an S
  S servant() {
    return (S) servant;
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
    LockedBuffer lb = locked();
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
    post(new Requests.Action<S>(requireNonNull(action, "action")));
  }

  @Override
  public void sendWhen(Guard<? super S> guard, ServantAction<? super S> action) {
    post(
        new Requests.GuardedAction<S>(
            requireNonNull(action, "action"), requireNonNull(guard, "guard")));
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
    return Proxies.create(this, servant(), type);
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
    // A release store, without a volatile store's fence: the activation only needs to see the
    // copy soon, and the senders go by the STOPPED bit that the compare-and-set above has set.
    STOPPED_COPY.setRelease(this, true);
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
    Core<?> sender = Carrier.running();
    Instant i = sender == null ? null : sender.instant();
    if (sender != null && i != null) {
      return new SyncFuture<>(sender, address(), i.sendSeq + 1);
    }
    return new ValueFuture<>(this);
  }

  /** Routes an envelope from the calling thread's object (if any) to this object. */
  void post(Envelope e) {
    Core<?> sender = Carrier.running();
    if (sender != null) {
      Instant i = sender.instant();
      if (i != null) {
        ++i.sendSeq;
      }
    }
    if (!e.bind(sender, this)) {
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
    // The rare fields are the receiving side's: a sender reads them only when it must.
    LockedBuffer lb = config.overflow() instanceof OverflowPolicy.DropOldest ? locked() : null;
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
      Link prev = (Link) TAIL.getAndSet(this, e);
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
      config.listener().onDropped(address(), e.event(this), config.overflow());
    } catch (RuntimeException t) {
      runtime.reportFailure(this, e.event(this), t);
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

  /**
   * One activation, on {@code carrier}'s thread: the object holds {@link #SCHEDULED}. An
   * asynchronous object processes {@link #BATCH} events, then goes on with another batch if no
   * other object waits for a worker, or goes back to the run queue if one does.
   */
  void run(Carrier carrier) {
    Core<?> outer = carrier.running; // a shutdown may run a stopped object inside an activation
    int outerTaken = carrier.taken;
    int outerBatch = carrier.takenBatch;
    Link outerCursor = carrier.cursor;
    if (outer != null && outerCursor != null) {
      outer.head = outerCursor; // this activation may take from the outer object's buffer
    }
    carrier.running = this;
    carrier.taken = 0;
    carrier.takenBatch = locked() == null ? takenBatch() : Integer.MAX_VALUE;
    carrier.cursor = null;
    int processed = 0;
    boolean more = false;
    CountDownLatch released = null;
    try {
      if ((state & STOPPED) != 0) {
        cancelQueued();
      } else if (config.mode() == Mode.SYNCHRONOUS) {
        Instant i = requireNonNull(instant());
        released = i.done;
        i.done = null;
        processed = runInstant(carrier);
      } else {
        Dispatcher dispatcher = runtime.dispatcher();
        carrier.cursor = head;
        int linger = LINGER_SPINS;
        int budget = BATCH;
        while (!stopped) {
          if (budget == 0) {
            if (!dispatcher.nothingWaiting(carrier)) {
              more = true;
              break;
            }
            runtime.countProcessed(carrier, processed);
            processed = 0;
            budget = BATCH;
          }
          Envelope e = takeProcessable(carrier);
          if (e == null) {
            linger = lingerForEvents(carrier, linger);
            if (linger < 0) {
              break;
            }
            continue;
          }
          processOne(carrier, e);
          processed++;
          budget--;
        }
      }
    } finally {
      Link cursor = carrier.cursor;
      if (cursor != null) {
        head = cursor;
      }
      returnTaken(carrier);
      carrier.running = outer;
      carrier.taken = outerTaken;
      carrier.takenBatch = outerBatch;
      carrier.cursor = outer != null && outerCursor != null ? outer.head : null;
      runtime.countProcessed(carrier, processed);
      if (more) {
        runtime.dispatcher().requeue(this); // fairness: the back of the shared queue
      } else {
        roomMade();
        if (!stopped) {
          restub(); // a stopped object does not go idle: one compare-and-set less as it stops
        }
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
  private int lingerForEvents(Carrier carrier, int spins) {
    Dispatcher dispatcher = runtime.dispatcher();
    if (!dispatcher.nothingWaiting(carrier)) {
      // Another object waits for this worker (as with many busy objects, each mostly idle): go
      // idle at once, without counting as a spinner for a moment, a shared write and its undoing.
      return -1;
    }
    returnTaken(carrier); // while it lingers, the object's count of queued events is exact
    LockedBuffer lb = locked();
    // The lingering worker watches the run queue too (nothingWaiting), so it counts as a spinning
    // worker: a sender that schedules another object meanwhile wakes no parked worker for it.
    dispatcher.lingerBegins(carrier);
    // The buffer's last link is the line the sender writes on every send: read it at growing
    // intervals (1, 2, 4 ... 64 spins), so that a sender streaming to this object mostly writes a
    // line this core does not hold, and the events that came meanwhile are taken in one go.
    int wait = 1;
    while (spins > 0 && dispatcher.nothingWaiting(carrier)) {
      for (int i = 0; i < wait; i++) {
        Thread.onSpinWait();
      }
      spins -= wait;
      wait = Math.min(wait << 1, LINGER_MAX_INTERVAL);
      if (lb != null ? lb.hasUnseen() : requireNonNull(carrier.cursor).next() != null) {
        dispatcher.lingerEnds(carrier);
        return Math.max(spins, 0);
      }
    }
    return -1; // the worker keeps counting as spinning: it goes on to poll the run queue
  }

  /**
   * Going idle with an empty buffer: this object becomes its buffer's first node again, so that an
   * idle object keeps no envelope alive (an envelope is 40 to 48 bytes, half an idle object's
   * budget). One compare-and-set per activation that empties the buffer; a sender that linked an
   * event meanwhile makes it fail, and the event's predecessor stays first. Consumer only.
   */
  private void restub() {
    Link h = head;
    if (h == this || config.mode() != Mode.ASYNCHRONOUS || h.next() != null) {
      return;
    }
    // This object left the chain when its successor was taken: no sender links to it any more.
    setNext(null);
    if (TAIL.compareAndSet(this, h, this)) {
      head = this;
    }
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
    LockedBuffer lb = locked();
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

  private void taken(Carrier carrier) {
    if (++carrier.taken >= carrier.takenBatch) {
      returnTaken(carrier);
    }
  }

  /**
   * Returns the places of the events this object's activation has taken so far, if the calling
   * thread is running it (before it parks in a wait by necessity, so its buffer's count is exact).
   */
  void returnTaken() {
    Carrier c = Carrier.current();
    if (c != null && c.running == this) {
      returnTaken(c);
    }
  }

  /** Returns the places of the events taken so far. Consumer only. */
  private void returnTaken(Carrier carrier) {
    int t = carrier.taken;
    if (t == 0) {
      return;
    }
    carrier.taken = 0;
    int left = (int) SIZE.getAndAdd(this, -t) - t;
    // Wake blocked senders at half capacity, not for every place: a park and an unpark per event
    // would make a full buffer far slower than a half-empty one.
    if (left <= config.capacity() >> 1) {
      roomMade();
    }
  }

  private void processOne(Carrier carrier, Envelope e) {
    taken(carrier);
    try {
      Rare r = rare;
      GuardFailure g = r == null ? null : r.guardFailure;
      if (g != null && g.envelope() == e) {
        r.guardFailure = null;
        throw new IllegalStateException("the guard of " + e + " threw " + g.error(), g.error());
      }
      e.process(this);
    } catch (Throwable t) {
      ActiveRuntimeErrors.throwIfFatal(t);
      e.failed(t);
      runtime.reportFailure(this, e.event(this), t);
    } finally {
      Rare r = rare;
      if (r != null) {
        r.dirty = true;
      }
      e.clear();
    }
  }

  /** The oldest processable event, or null if none; consumer only. */
  private @Nullable Envelope takeProcessable(Carrier carrier) {
    Rare r = rare;
    if (r != null) {
      LockedBuffer lb = r.locked;
      if (lb != null) {
        Envelope e = lb.takeProcessable(this, r.dirty);
        r.dirty = false;
        return e;
      }
      ArrayDeque<Envelope> deferred = r.deferred;
      if (deferred != null && !deferred.isEmpty() && r.dirty) {
        r.dirty = false;
        for (Iterator<Envelope> it = deferred.iterator(); it.hasNext(); ) {
          Envelope d = it.next();
          if (processableSafely(d)) {
            it.remove(); // the oldest first: mostly the deque's first, removed in constant time
            return d;
          }
        }
      }
      r.dirty = false;
    }
    for (; ; ) {
      Envelope e = pollInbox(carrier);
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
      rare().guardFailure = new GuardFailure(e, t);
      return true;
    }
  }

  /**
   * The next linked event, or null. It does not read {@link #tail}: that line is written by every
   * send, and a consumer reading it per event makes it bounce between cores. An event whose sender
   * has swapped the tail but not linked it yet is seen on a later poll (the end-of-activation check
   * reads the tail, so it is never lost).
   */
  private @Nullable Envelope pollInbox(Carrier carrier) {
    Link n = requireNonNull(carrier.cursor).next();
    if (n != null) {
      carrier.cursor = n;
    }
    return (Envelope) n; // this object is only ever the first node, never a linked one
  }

  /**
   * As {@link #pollInbox(Carrier)}, but waits for a link in progress (all events up to the tail).
   */
  private @Nullable Envelope pollInboxToTail() {
    Link h = head;
    Link n = h.next();
    if (n == null) {
      if (h == tail) {
        return null;
      }
      while ((n = h.next()) == null) {
        Thread.onSpinWait();
      }
    }
    head = n;
    return (Envelope) n;
  }

  private void appendDeferred(Envelope e) {
    Rare r = rare();
    ArrayDeque<Envelope> deferred = r.deferred;
    if (deferred == null) {
      deferred = new ArrayDeque<>();
      r.deferred = deferred;
    }
    deferred.addLast(e);
  }

  /** Stopped: discard everything queued, failing the futures. */
  private void cancelQueued() {
    ObjectStoppedException stopped = new ObjectStoppedException(address());
    List<Envelope> all = new ArrayList<>();
    LockedBuffer lb = locked();
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
    Rare r = rare;
    ArrayDeque<Envelope> deferred = r == null ? null : r.deferred;
    if (deferred != null) {
      into.addAll(deferred);
      deferred.clear();
    }
  }

  // ---------------------------------------------------------------- blocked senders

  /** Parks the sender until there may be room, the object stopped, or the deadline passed. */
  private boolean awaitRoom(long deadline) {
    Core<?> sender = Carrier.running();
    if (sender != null) {
      sender.returnTaken();
    }
    var q = rare().blocked;
    Thread me = Thread.currentThread();
    Dispatcher.beforeBlock();
    try {
      for (; ; ) {
        // Queued before the check: a consumer that makes room after the check sees it and wakes
        // it (it takes the queue's senders when it wakes them).
        q.add(me);
        if (size < config.capacity() || (state & STOPPED) != 0) {
          return true;
        }
        long remaining = deadline - runtime.timeSource().nanoTime();
        if (remaining <= 0) {
          return false;
        }
        java.util.concurrent.locks.LockSupport.parkNanos(this, remaining);
        q.remove(me);
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

  /**
   * Wakes the blocked senders, if any, after the buffer made room, and takes them out of the queue:
   * a sender that finds the buffer still full queues itself again, so while nobody waits this is
   * one read of an empty queue.
   */
  private void roomMade() {
    Rare r = rare;
    if (r != null) {
      var q = r.blocked;
      for (Thread t = q.poll(); t != null; t = q.poll()) {
        java.util.concurrent.locks.LockSupport.unpark(t);
      }
    }
  }

  // ---------------------------------------------------------------- synchronous mode

  /** Clock, phase 1 of a release: fixes which events belong to this instant. */
  void beginInstant() {
    LockedBuffer lb = locked();
    if (lb != null) {
      lb.markRelease();
    } else {
      // The last node linked now: events whose place was reserved but that are not linked yet
      // were sent at the same time as the release, and belong to the next instant.
      requireNonNull(instant()).releasedTail = tail;
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
        Instant i = requireNonNull(instant());
        i.number = instant;
        i.done = done;
        runtime.dispatcher().schedule(this);
        return true;
      }
    }
  }

  /**
   * By sender address: the senders are objects of this runtime, so by their numbers, and events
   * from outside any object (0) first. The sort is stable, and one sender's events reach the buffer
   * (and the deferred list) in the order it sent them, so each sender's events stay in send order.
   */
  private static final Comparator<Envelope> INSTANT_ORDER =
      Comparator.comparingLong((Envelope e) -> e.from == null ? 0 : e.from.id);

  /** Retries skipped events oldest first, restarting after each one processed. */
  private int retrySkipped(Carrier carrier, List<Envelope> skipped) {
    int processed = 0;
    boolean progress = true;
    while (progress && (state & STOPPED) == 0) {
      progress = false;
      for (int i = 0; i < skipped.size(); i++) {
        Envelope e = skipped.get(i);
        if (processableSafely(e)) {
          skipped.remove(i);
          processOne(carrier, e);
          processed++;
          progress = true;
          break;
        }
      }
    }
    return processed;
  }

  /** Takes every event waiting at the release, in a deterministic order, then the cycle. */
  private int runInstant(Carrier carrier) {
    List<Envelope> batch = new ArrayList<>();
    LockedBuffer lb = locked();
    if (lb != null) {
      lb.takeReleased(batch);
    } else {
      takeDeferred(batch);
      Link last = requireNonNull(instant()).releasedTail;
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
    int processed = processInstant(carrier, batch, lb);
    if (servant instanceof ReactiveCycle rc && (state & STOPPED) == 0) {
      try {
        rc.onCycle(requireNonNull(instant()).number);
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
  private int processInstant(Carrier carrier, List<Envelope> batch, @Nullable LockedBuffer lb) {
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
      processOne(carrier, e);
      processed++;
      processed += retrySkipped(carrier, skipped);
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

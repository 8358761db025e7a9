package org.armgals.active;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedDeque;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.ReentrantLock;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs the activations of a runtime's objects on worker virtual threads.
 *
 * <p>Objects with work are in one shared run queue; {@code parallelism} workers take them. A worker
 * with nothing to do spins briefly, then parks; a producer wakes a parked worker only if none is
 * spinning. A worker that parks inside an activation (a wait by necessity, a sender blocked by a
 * full buffer) calls {@link #beforeBlock()}: if fewer than {@code parallelism} workers are left
 * unblocked, another is started, so a waiting object holds only its own virtual thread and never
 * stalls the others. Surplus workers retire when they run out of work.
 */
final class Dispatcher {
  private static final Logger LOG = LoggerFactory.getLogger(Dispatcher.class);

  /**
   * The longest an idle worker spins before it parks. For a request/reply pair the spin must
   * outlast the time a parked thread takes to wake (tens of microseconds on a virtual machine), or
   * both sides fall into parking every time; measured: 40 µs of spinning gave 10k round trips/s,
   * 100 µs and more gave 0.5-2M/s.
   */
  static final long MAX_SPIN_NANOS = 200_000;

  /**
   * The shortest spin. Spinning adapts per worker ({@link AdaptiveSpin}, the worker's idle
   * strategy): a spin that finds work doubles the next one, a spin that finds nothing halves it, so
   * a worker that has nothing to do stops taking the core from the threads that do (on a small
   * machine, an outside sender is one of them). A worker woken for work from another runtime within
   * {@link #MAX_SPIN_NANOS} of parking spins twice as long as its failed spin next time (decision
   * 0033).
   */
  static final long MIN_SPIN_NANOS = 5_000;

  /**
   * The looks at the run queue an idle worker makes between two steps of its {@link AdaptiveSpin}
   * (each step reads the clock): the loop keeps its counter in a register.
   */
  static final int SPIN_BATCH = 32;

  /** A worker handing objects to itself reads the clock once per this many + 1 hand-overs. */
  static final int HANDOFF_CHECK_MASK = 63;

  /**
   * The shortest time between two wake-ups for hand-overs by one worker: on a quiet machine it
   * costs at most one wake-up and one short spin per 100 µs of a chain of hand-overs; on a loaded
   * one it keeps a second worker ready to take the chain over (decision 0046).
   */
  static final long HANDOFF_WAKE_NANOS = 100_000;

  /** True on a transport's thread while it queues events and requests from another runtime. */
  private static final ThreadLocal<Boolean> INBOUND = ThreadLocal.withInitial(() -> false);

  /**
   * One worker thread; {@code running} is true while it polls or runs an activation. {@code next}
   * holds an object this worker woke while the slot was empty: it runs it next, on the same core,
   * unless a spinning worker steals it first (Go's {@code runnext}). Only this worker sets it;
   * others only take it (a compare-and-set to null).
   */
  private static final class Worker extends Carrier {
    final Dispatcher dispatcher;
    volatile @Nullable Thread thread;
    volatile boolean running;
    volatile @Nullable Core<?> next;

    /** How this worker spins on the run queue before it parks; the worker's only. */
    final AdaptiveSpin idle;

    /**
     * Whether this worker holds one unit of {@code spinning}: taken while its object lingers for
     * events, kept when the activation ends into {@link #spin}, which releases it. The worker's
     * only.
     */
    boolean counted;

    /** Set by the thread that unparks this worker to hand it work from another runtime. */
    volatile boolean wokenForInbound;

    /** Events processed by this worker: written by it only (release), summed by stats. */
    volatile long processed;

    /** Objects this worker handed to itself through {@code next}; the worker's only. */
    int handoffs;

    /** When this worker last woke another for its hand-overs; the worker's only. */
    long handoffWakeAt;

    Worker(Dispatcher dispatcher) {
      this.dispatcher = dispatcher;
      this.idle =
          new AdaptiveSpin(
              dispatcher.runtime.timeSource(), MIN_SPIN_NANOS, MAX_SPIN_NANOS, MAX_SPIN_NANOS / 4);
    }
  }

  private static final VarHandle NEXT;
  private static final VarHandle PROCESSED;

  static {
    try {
      NEXT = MethodHandles.lookup().findVarHandle(Worker.class, "next", Core.class);
      PROCESSED = MethodHandles.lookup().findVarHandle(Worker.class, "processed", long.class);
    } catch (ReflectiveOperationException e) {
      throw new ExceptionInInitializerError(e);
    }
  }

  private final String name;
  private final int parallelism;
  private final RunQueue runQueue = new RunQueue();
  private final java.util.concurrent.atomic.LongAdder processedElsewhere =
      new java.util.concurrent.atomic.LongAdder();
  private final int maxSpinners;
  private final java.util.concurrent.atomic.LongAdder wakeUps =
      new java.util.concurrent.atomic.LongAdder();

  /**
   * Parked workers, the last parked first: the one woken is the one that parked last, whose spin
   * has learned the pace of the work that wakes it, and whose data is still in cache.
   */
  private final ConcurrentLinkedDeque<Worker> idle = new ConcurrentLinkedDeque<>();

  /**
   * Workers in {@link #parkIdle}, counted before they queue themselves in {@link #idle}: a sender
   * finds that none is parked with one read, instead of a look into the deque.
   */
  private final AtomicInteger parked = new AtomicInteger();

  private final Set<Worker> workers = ConcurrentHashMap.newKeySet();
  private volatile Worker[] snapshot = new Worker[0];
  private final AtomicInteger alive = new AtomicInteger();
  private final AtomicInteger blocked = new AtomicInteger();
  private final AtomicInteger spinning = new AtomicInteger();
  private final AtomicInteger started = new AtomicInteger();
  private final ReentrantLock quietLock = new ReentrantLock();
  private final Condition quiet = quietLock.newCondition();
  private final RuntimeImpl runtime;
  private volatile boolean draining;
  private volatile boolean terminated;

  Dispatcher(RuntimeImpl runtime, String name, int parallelism) {
    this.runtime = runtime;
    this.name = name;
    this.parallelism = parallelism;
    this.maxSpinners = Math.max(1, parallelism / 2);
    for (int i = 0; i < parallelism; i++) {
      alive.incrementAndGet();
      startWorker();
    }
  }

  /**
   * Queues an object that holds its SCHEDULED flag. Any thread. From a worker whose {@code next}
   * slot is empty, the object goes there: an object woken by another runs on the same core, with
   * its data still in cache. Otherwise it goes to the shared queue.
   */
  void schedule(Core<?> core) {
    if (terminated) {
      Carrier.runByHand(
          core); // only stopped objects get here: the activation discards their events
      return;
    }
    if (Carrier.current() instanceof Worker w && w.dispatcher == this && w.next == null) {
      // Only this worker fills its slot, and a thief only empties it (a compare-and-set from the
      // object to null), so an empty slot stays empty until this store: no atomic exchange. An
      // occupied slot keeps its object, and this one joins the shared queue, where the other
      // workers find it (decision 0083).
      NEXT.setRelease(w, core);
      // No wake-up: this worker runs it next. Waking another one here only made it spin on this
      // slot (measured: thread ring and ping-pong 40-65% faster without). A spinning worker still
      // steals it, and a worker about to block hands it over. But at most once per
      // HANDOFF_WAKE_NANOS of hand-overs a parked worker is woken: it spins and steals the slot if
      // this worker's thread has lost its core meanwhile (a loaded machine), so that a chain of
      // hand-overs does not wait for one descheduled thread while another could run.
      if ((++w.handoffs & HANDOFF_CHECK_MASK) == 0) {
        long now = runtime.timeSource().nanoTime();
        if (now - w.handoffWakeAt >= HANDOFF_WAKE_NANOS) {
          w.handoffWakeAt = now;
          wakeIfNoneSpinning();
        }
      }
      return;
    }
    requeue(core);
  }

  /**
   * Whether the calling thread is one of this dispatcher's workers and no other object waits for
   * it: the shared queue is empty and the worker's own next slot too. A lingering object gives way
   * to any waiting one; on a thread driving the dispatcher by hand it never lingers.
   */
  boolean nothingWaiting(Carrier carrier) {
    return carrier instanceof Worker w
        && w.dispatcher == this
        && w.next == null
        && runQueue.isEmpty();
  }

  /**
   * The calling worker's object lingers for events, watching the run queue: it counts as a spinning
   * worker (if fewer than the most spinners spin), so that work queued meanwhile wakes no parked
   * worker; it will take that work itself.
   */
  void lingerBegins(Carrier carrier) {
    if (carrier instanceof Worker w && w.dispatcher == this && !w.counted) {
      if (spinning.incrementAndGet() > maxSpinners) {
        spinning.decrementAndGet();
      } else {
        w.counted = true;
      }
    }
  }

  /** The calling worker's object found events after lingering: it no longer counts as spinning. */
  void lingerEnds(Carrier carrier) {
    if (carrier instanceof Worker w && w.counted) {
      w.counted = false;
      spinning.decrementAndGet();
    }
  }

  /** Queues an object at the back of the shared queue (an object that used up its batch). */
  void requeue(Core<?> core) {
    if (terminated) {
      Carrier.runByHand(core);
      return;
    }
    runQueue.offer(core);
    wakeIfNoneSpinning();
  }

  /**
   * Wakes a parked worker unless one is spinning (a spinner finds the work by itself). While a
   * stream of messages flows, a worker is nearly always spinning, so this rarely unparks.
   */
  private void wakeIfNoneSpinning() {
    if (spinning.get() == 0 && parked.get() > 0) {
      Worker w = idle.pollFirst();
      if (w != null) {
        if (INBOUND.get()) {
          w.wokenForInbound = true;
        }
        wakeUps.increment();
        LockSupport.unpark(w.thread);
      }
    }
  }

  /**
   * Marks the calling thread as a transport's, queueing what came from another runtime, until
   * {@link #leaveInbound}: a worker it wakes then knows the work came from another runtime.
   *
   * @return whether it was marked already (to pass to {@link #leaveInbound})
   */
  static boolean enterInbound() {
    boolean was = INBOUND.get();
    INBOUND.set(true);
    return was;
  }

  static void leaveInbound(boolean was) {
    INBOUND.set(was);
  }

  // ---------------------------------------------------------------- blocking inside activations

  /**
   * The calling thread is about to park; if it is a worker, it hands its {@code next} object to the
   * others and keeps parallelism up.
   */
  static void beforeBlock() {
    if (Carrier.current() instanceof Worker w) {
      w.dispatcher.lingerEnds(w);
      Core<?> n = (Core<?>) NEXT.getAndSet(w, null);
      if (n != null) {
        w.dispatcher.requeue(n);
      }
      w.dispatcher.compensate();
    }
  }

  /** The calling thread is back from parking. */
  static void afterBlock() {
    if (Carrier.current() instanceof Worker w) {
      w.dispatcher.blocked.decrementAndGet();
    }
  }

  private void compensate() {
    int b = blocked.incrementAndGet();
    if (terminated) {
      return;
    }
    for (; ; ) {
      int a = alive.get();
      if (a - b >= parallelism) {
        return;
      }
      if (alive.compareAndSet(a, a + 1)) {
        startWorker();
        return;
      }
    }
  }

  // ---------------------------------------------------------------- workers

  private void startWorker() {
    Worker w = new Worker(this);
    workers.add(w);
    snapshot = workers.toArray(new Worker[0]);
    Thread t =
        Thread.ofVirtual()
            .name(name + "-worker-" + started.incrementAndGet())
            .unstarted(() -> loop(w));
    w.thread = t;
    t.start();
  }

  private void loop(Worker w) {
    Carrier.install(w);
    boolean retired = false;
    try {
      while (!terminated) {
        w.running = true;
        Core<?> c = w.next == null ? null : (Core<?>) NEXT.getAndSet(w, null);
        if (c == null) {
          c = runQueue.poll();
        }
        if (c == null) {
          c = spin(w);
        } else {
          lingerEnds(w);
        }
        if (c == null) {
          w.running = false;
          signalIfDraining();
          if (retireIfSurplus()) {
            retired = true;
            return;
          }
          long parkedAt = runtime.timeSource().nanoTime();
          parkIdle(w);
          if (w.wokenForInbound) {
            w.wokenForInbound = false;
            // Work from another runtime, after a wake-up that is on its round trip's path: if it
            // came within the longest spin, a longer spin would have found it (decision 0033).
            w.idle.blockedFor(runtime.timeSource().nanoTime() - parkedAt);
          } else {
            w.idle.reset();
          }
          continue;
        }
        try {
          c.run(w);
        } catch (Throwable t) {
          ActiveRuntimeErrors.throwIfFatal(t);
          LOG.error("activation of {} failed outside its events", c.address(), t);
        }
      }
    } finally {
      w.running = false;
      lingerEnds(w);
      if (!retired && !terminated) {
        // A fatal error ended this worker (it was rethrown, not swallowed): replace it so the
        // runtime keeps its parallelism.
        startWorker();
      }
      Core<?> n = (Core<?>) NEXT.getAndSet(w, null);
      if (n != null) {
        requeue(n);
      }
      processedElsewhere.add(w.processed); // a retired worker's count stays in the total
      workers.remove(w);
      snapshot = workers.toArray(new Worker[0]);
      signalIfDraining();
    }
  }

  /**
   * Polls the shared queue for the worker's spin length; in the last quarter it also steals the
   * {@code next} object of another worker, which is then busy with something else.
   */
  private @Nullable Core<?> spin(Worker self) {
    // At most half the workers spin at a time (Go's rule): more spinners than that only compete
    // for the cores with the threads that do the work.
    if (self.counted) {
      self.counted = false; // the unit taken while its last object lingered: released below
    } else if (spinning.incrementAndGet() > maxSpinners) {
      spinning.decrementAndGet();
      return runQueue.poll();
    }
    try {
      AdaptiveSpin idle = self.idle;
      while (!terminated && idle.spin()) { // a step of the strategy: a batch of looks
        boolean late = idle.late();
        for (int i = 0; i < SPIN_BATCH; i++) {
          Thread.onSpinWait();
          Core<?> c = runQueue.poll();
          if (c == null && late) {
            c = steal(self);
          }
          if (c != null) {
            idle.reset(); // found while spinning: the next spin is longer
            return c;
          }
        }
      }
      return null;
    } finally {
      spinning.decrementAndGet();
    }
  }

  private @Nullable Core<?> steal(Worker self) {
    for (Worker o : snapshot) {
      Core<?> c = o.next;
      if (o != self && c != null && NEXT.compareAndSet(o, c, null)) {
        return c;
      }
    }
    return null;
  }

  private boolean retireIfSurplus() {
    for (; ; ) {
      int a = alive.get();
      if (a - blocked.get() <= parallelism) {
        return false;
      }
      if (alive.compareAndSet(a, a - 1)) {
        return true;
      }
    }
  }

  private void parkIdle(Worker w) {
    // Counted, then queued, then the run queue checked: a sender queues its object, then reads the
    // count (both atomic), so either it sees this worker or this worker sees its object.
    parked.incrementAndGet();
    try {
      idle.addFirst(w);
      if (!runQueue.isEmpty() || terminated) {
        idle.remove(w);
        return;
      }
      LockSupport.park(this);
      idle.remove(w);
    } finally {
      parked.decrementAndGet();
    }
  }

  // -------------------------------------------------------- invoker (a cycle is a method)

  /**
   * One worker step on the calling thread: runs one activation of the next queued object. For a
   * dispatcher with no workers, driven by hand (tests, model checking).
   *
   * @return false if no object was queued
   */
  boolean runOne() {
    for (; ; ) {
      Core<?> c = runQueue.poll();
      if (c != null) {
        Carrier.runByHand(c);
        return true;
      }
      if (runQueue.isEmpty()) {
        return false;
      }
      Thread.onSpinWait(); // another thread is polling
    }
  }

  /** How many times a parked worker was woken for work. */
  long wakeUps() {
    return wakeUps.sum();
  }

  /** How many worker threads are inside their loop. */
  int liveWorkers() {
    return workers.size();
  }

  /**
   * Counts {@code n} events processed by the calling thread: on a worker, in its own field (no
   * shared write per activation); elsewhere (a thread driving the dispatcher by hand) in a shared
   * adder.
   */
  void countProcessed(Carrier carrier, int n) {
    if (carrier instanceof Worker w && w.dispatcher == this) {
      PROCESSED.setRelease(w, w.processed + n);
    } else {
      processedElsewhere.add(n);
    }
  }

  /** Events processed so far, by live workers, retired ones and other threads. */
  long processed() {
    long sum = processedElsewhere.sum();
    for (Worker w : snapshot) {
      sum += w.processed;
    }
    return sum;
  }

  // ---------------------------------------------------------------- shutdown

  /** Whether no object is queued to run and no worker runs an activation. */
  private boolean isQuiet() {
    if (!runQueue.isEmpty()) {
      return false;
    }
    for (Worker w : workers) {
      if (w.running || w.next != null) {
        return false;
      }
    }
    return runQueue.isEmpty();
  }

  private void signalIfDraining() {
    if (draining) {
      quietLock.lock();
      try {
        quiet.signalAll();
      } finally {
        quietLock.unlock();
      }
    }
  }

  /** Waits until no object has work, at most until {@code deadline} (runtime time). */
  boolean awaitQuiet(long deadline) {
    draining = true;
    quietLock.lock();
    try {
      while (!isQuiet()) {
        long remaining = deadline - runtime.timeSource().nanoTime();
        if (remaining <= 0) {
          return false;
        }
        // Bounded wait: a wake-up can come from a worker that retired or parked without work.
        quiet.await(Math.min(remaining, TimeUnit.MILLISECONDS.toNanos(10)), TimeUnit.NANOSECONDS);
      }
      return true;
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      return false;
    } finally {
      quietLock.unlock();
    }
  }

  /** Interrupts the workers that are inside an activation (a cancelling shutdown). */
  void interruptRunning() {
    for (Worker w : workers) {
      Thread t = w.thread;
      if (w.running && t != null) {
        t.interrupt();
      }
    }
  }

  /**
   * Stops every worker once it is done with its activation, waits for them until {@code deadline},
   * then runs what is still queued on the calling thread: objects are all stopped by then, so their
   * activations only discard events and fail futures. A send that races the shutdown finds {@link
   * #terminated} set and is handled the same way by its own thread.
   */
  void terminate(long deadline) {
    terminated = true;
    for (Worker w : snapshot) {
      Thread t = w.thread;
      LockSupport.unpark(t);
    }
    for (Worker w : snapshot) {
      Thread t = w.thread;
      long remaining = deadline - runtime.timeSource().nanoTime();
      if (t != null && t != Thread.currentThread() && remaining > 0) {
        try {
          t.join(java.time.Duration.ofNanos(remaining));
        } catch (InterruptedException e) {
          Thread.currentThread().interrupt();
          break;
        }
      }
    }
    for (Core<?> c = runQueue.poll(); c != null; c = runQueue.poll()) {
      Carrier.runByHand(c);
    }
  }
}

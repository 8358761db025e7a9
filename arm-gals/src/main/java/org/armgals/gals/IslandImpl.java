package org.armgals.gals;

import static java.util.Objects.requireNonNull;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.BooleanSupplier;
import javax.management.ObjectName;
import org.armgals.active.ActiveContext;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Clock;
import org.armgals.active.ManualClock;
import org.armgals.active.ObjectConfig;
import org.armgals.active.TimeSource;
import org.armgals.active.spi.CycleRecorder;
import org.armgals.active.spi.DeadlinePacer;
import org.armgals.kernel.AdaptationPoint;
import org.armgals.kernel.BehavioralMeta;
import org.armgals.kernel.Entity;
import org.armgals.kernel.EntityOptions;
import org.armgals.kernel.NotificationPolicy;
import org.armgals.kernel.StructuralMeta;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * An island: arm-active's manual clock does the two-phase release of the entities; the island owns
 * the pacing (by hand, or a real-time runner) so that it can put adaptation before or after the
 * release and keep its schedule by its overrun policy (decision 0017).
 */
final class IslandImpl implements Island {
  private static final Logger LOG = LoggerFactory.getLogger(IslandImpl.class);

  private final String name;
  private final ActiveRuntime runtime;
  private final Duration period;
  private final long periodNanos;
  private final AdaptationPoint adaptationPoint;
  private final OverrunPolicy overrunPolicy;
  private final TimeSource time;
  private final DeadlinePacer pacer;
  private final BooleanSupplier isClosed = () -> this.closed;
  private final ObjectConfig config;
  private final ManualClock clock;
  private final CycleRecorder stats;
  private final Trace trace;
  private final CopyOnWriteArrayList<EntityImpl<?>> entities = new CopyOnWriteArrayList<>();
  private final ConcurrentLinkedQueue<PendingAdaptation> requests = new ConcurrentLinkedQueue<>();
  private final ReentrantLock cycling = new ReentrantLock();
  private final @Nullable ObjectName mbean;
  private volatile boolean closed;
  private @Nullable Thread runner;

  IslandImpl(Island.Builder b, DeadlinePacer pacer) {
    this.name = b.name;
    this.runtime = b.runtime;
    this.period = b.period;
    this.periodNanos = b.period.toNanos();
    this.adaptationPoint = b.adaptationPoint;
    this.overrunPolicy = b.overrunPolicy;
    this.time = b.timeSource;
    this.pacer = pacer;
    this.clock = Clock.manual(b.period);
    this.config = ObjectConfig.synchronous(clock).withCapacity(b.capacity);
    this.stats = new CycleRecorder(period);
    this.trace = new Trace(b.tracing);
    this.mbean = b.jmx ? IslandJmx.register(this, runtime.name()) : null;
  }

  @Override
  public String name() {
    return name;
  }

  @Override
  public Duration period() {
    return period;
  }

  @Override
  public AdaptationPoint adaptationPoint() {
    return adaptationPoint;
  }

  @Override
  public OverrunPolicy overrunPolicy() {
    return overrunPolicy;
  }

  @Override
  public <S> ReactiveEntity<S> spawn(String name, S state, Reaction<S> main) {
    requireNonNull(name, "name");
    requireNonNull(state, "state");
    requireNonNull(main, "main");
    if (name.isBlank()) {
      throw new IllegalArgumentException("entity name must not be blank, was '" + name + "'");
    }
    synchronized (entities) {
      if (closed) {
        throw new IllegalStateException("island " + this.name + " is closed");
      }
      for (EntityImpl<?> e : entities) {
        if (e.name().equals(name)) {
          throw new IllegalArgumentException(
              "entity name " + name + " is already used in island " + this.name);
        }
      }
      EntityImpl<S> entity = new EntityImpl<>(name, state, this, main);
      entity.bind(runtime.spawn(entity, config));
      entities.add(entity);
      return entity;
    }
  }

  @Override
  public Entity spawn(
      StructuralMeta<?> kind, String name, BehavioralMeta meta, NotificationPolicy notification) {
    requireNonNull(kind, "kind");
    requireNonNull(name, "name");
    requireNonNull(meta, "meta");
    requireNonNull(notification, "notification");
    synchronized (entities) {
      if (closed) {
        throw new IllegalStateException("island " + this.name + " is closed");
      }
      return kind.newEntity(name, meta, new EntityOptions(config, notification, adaptationPoint));
    }
  }

  @Override
  public Entity spawn(
      StructuralMeta<?> kind, String name, BehavioralMeta meta, EntityOptions options) {
    requireNonNull(meta, "meta");
    return spawnKernelEntity(kind, name, meta, options);
  }

  @Override
  public Entity spawn(StructuralMeta<?> kind, String name, EntityOptions options) {
    return spawnKernelEntity(kind, name, null, options);
  }

  private Entity spawnKernelEntity(
      StructuralMeta<?> kind, String name, @Nullable BehavioralMeta meta, EntityOptions options) {
    requireNonNull(kind, "kind");
    requireNonNull(name, "name");
    requireNonNull(options, "options");
    synchronized (entities) {
      if (closed) {
        throw new IllegalStateException("island " + this.name + " is closed");
      }
      EntityOptions islands =
          new EntityOptions(
              config,
              options.notification(),
              adaptationPoint,
              options.program(),
              options.lockStep(),
              options.lockStepTimeout());
      return meta == null ? kind.newEntity(name, islands) : kind.newEntity(name, meta, islands);
    }
  }

  @Override
  public EntityOptions entityOptions() {
    return new EntityOptions(config, NotificationPolicy.all(), adaptationPoint);
  }

  @Override
  public List<ReactiveEntity<?>> entities() {
    return List.copyOf(entities);
  }

  @Override
  public long step() {
    synchronized (this) {
      if (runner != null) {
        throw new IllegalStateException("island " + name + " is started; it cannot be stepped");
      }
    }
    if (ActiveContext.current().map(o -> o.config().clock() == clock).orElse(false)) {
      throw new IllegalStateException("an entity of island " + name + " cannot step it");
    }
    long now = time.nanoTime();
    return cycle(now, 0);
  }

  @Override
  public void step(long cycles) {
    if (cycles < 0) {
      throw new IllegalArgumentException("cycles must be >= 0, was " + cycles);
    }
    for (long i = 0; i < cycles; i++) {
      step();
    }
  }

  /**
   * Runs one cycle released at {@code releasedAt}, {@code lateness} behind its schedule: the
   * adaptation point, the release, the trace; records the figures.
   *
   * @return the instant
   */
  long cycle(long releasedAt, long lateness) {
    cycling.lock();
    try {
      if (closed) {
        throw new IllegalStateException("island " + name + " is closed");
      }
      long k = clock.instant() + 1;
      long adaptation = 0;
      int applied = 0;
      if (adaptationPoint == AdaptationPoint.BEGIN_OF_CYCLE) {
        long t = time.nanoTime();
        applied = applyRequests(k);
        adaptation = time.nanoTime() - t;
      }
      clock.step();
      if (adaptationPoint == AdaptationPoint.END_OF_CYCLE) {
        long t = time.nanoTime();
        applied = applyRequests(k);
        adaptation = time.nanoTime() - t;
      }
      long end = time.nanoTime();
      String prefix = name + " " + k + " ";
      for (EntityImpl<?> e : entities) {
        e.drainTrace(line -> trace.add(prefix + line));
      }
      stats.record(releasedAt, lateness, end - releasedAt, adaptation, applied);
      return k;
    } finally {
      cycling.unlock();
    }
  }

  private int applyRequests(long k) {
    int n = requests.size(); // those made before this point; later ones wait for the next
    int applied = 0;
    for (int i = 0; i < n; i++) {
      PendingAdaptation a = requests.poll();
      if (a == null) {
        break;
      }
      trace.add(name + " " + k + " " + a.entity().name() + " adapt " + a.description());
      try {
        a.change().run();
      } catch (RuntimeException e) {
        failed(a.entity(), a.description(), k, e);
      }
      applied++;
    }
    return applied;
  }

  void request(PendingAdaptation adaptation) {
    if (closed) {
      throw new IllegalStateException("island " + name + " is closed");
    }
    requests.add(adaptation);
  }

  void failed(EntityImpl<?> entity, String what, long instant, Exception e) {
    stats.failure();
    LOG.warn("island {} instant {}: {} of {} failed", name, instant, what, entity.name(), e);
  }

  ActiveRuntime runtime() {
    return runtime;
  }

  boolean tracing() {
    return trace.on();
  }

  /** Whole periods in {@code d}, rounded up, at least one. */
  long periodsIn(Duration d) {
    long nanos = d.toNanos();
    return Math.max(1, nanos / periodNanos + (nanos % periodNanos == 0 ? 0 : 1));
  }

  // ---- the real-time runner

  @Override
  public synchronized void start() {
    if (closed) {
      throw new IllegalStateException("island " + name + " is closed");
    }
    if (runner != null) {
      return;
    }
    Thread t = Thread.ofPlatform().name("armgals-island-" + name).daemon(true).unstarted(this::run);
    runner = t;
    t.start();
  }

  private void run() {
    Schedule schedule = new Schedule(periodNanos, overrunPolicy);
    long due = time.nanoTime() + periodNanos;
    while (!closed) {
      due = runOnce(schedule, due);
    }
  }

  /**
   * One turn of the runner (the invoker of tests): waits for the release due at {@code due}, runs
   * its cycle, and answers when the next one is due.
   */
  long runOnce(Schedule schedule, long due) {
    pacer.awaitUntil(due, isClosed);
    if (closed) {
      return due;
    }
    long released = time.nanoTime();
    try {
      cycle(released, released - due);
    } catch (RuntimeException e) {
      if (!closed) {
        LOG.error("island {}: a cycle failed", name, e);
      }
    }
    long next = schedule.next(due, time.nanoTime());
    stats.skipped(schedule.takeSkipped());
    return next;
  }

  @Override
  public long instant() {
    return clock.instant();
  }

  @Override
  public IslandStats stats() {
    CycleRecorder.Figures f = stats.snapshot();
    return new IslandStats(
        f.instants(),
        f.overruns(),
        f.skipped(),
        f.meanPeriod(),
        f.jitterP50(),
        f.jitterP99(),
        f.jitterMax(),
        f.cycleMax(),
        f.adaptations(),
        f.adaptationMax(),
        f.adaptationOverruns(),
        f.failures());
  }

  @Override
  public List<String> trace() {
    return trace.lines();
  }

  @Override
  public String traceHash() {
    return trace.hash();
  }

  @Override
  public void close() {
    Thread t;
    synchronized (this) {
      if (closed) {
        return;
      }
      closed = true;
      t = runner;
    }
    if (t != null && t != Thread.currentThread()) {
      LockSupport.unpark(t);
      boolean interrupted = false;
      for (; ; ) {
        try {
          t.join();
          break;
        } catch (InterruptedException e) {
          interrupted = true;
        }
      }
      if (interrupted) {
        Thread.currentThread().interrupt();
      }
    }
    cycling.lock();
    try {
      synchronized (entities) {
        for (EntityImpl<?> e : entities) {
          e.object().stop();
        }
      }
      clock.close();
      IslandJmx.unregister(mbean, name);
    } finally {
      cycling.unlock();
    }
  }

  @Override
  public String toString() {
    return "Island[" + name + ", period=" + period + ", instant=" + instant() + "]";
  }

  /** For tests: the entity's active object. */
  static ActiveObject<?> objectOf(ReactiveEntity<?> entity) {
    return ((EntityImpl<?>) entity).object();
  }
}

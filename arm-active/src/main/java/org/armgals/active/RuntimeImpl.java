package org.armgals.active;

import static java.util.Objects.requireNonNull;

import java.lang.management.ManagementFactory;
import java.time.Duration;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.BiConsumer;
import javax.management.JMException;
import javax.management.ObjectName;
import javax.management.StandardMBean;
import org.armgals.active.spi.ErrorHandler;
import org.armgals.active.spi.Transport;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** The runtime behind {@link ActiveRuntime}. */
final class RuntimeImpl implements ActiveRuntime {
  private static final Logger LOG = LoggerFactory.getLogger(RuntimeImpl.class);
  private static final int RUNNING = 0;
  private static final int STOPPING = 1;
  private static final int TERMINATED = 2;

  private final String name;
  private final Dispatcher dispatcher;
  private final ErrorHandler errorHandler;
  private final @Nullable Transport transport;
  private final TimeSource timeSource;
  private final ObjectTable objects = new ObjectTable();
  private final Set<ClockSupport> clocks = ConcurrentHashMap.newKeySet();
  private final AtomicInteger phase = new AtomicInteger(RUNNING);
  private final LongAdder dropped = new LongAdder();
  private final LongAdder rejected = new LongAdder();
  private final LongAdder failures = new LongAdder();
  private volatile boolean cleanShutdown;
  private final @Nullable ObjectName mbeanName;

  RuntimeImpl(
      String name,
      int workers,
      ErrorHandler errorHandler,
      @Nullable Transport transport,
      TimeSource timeSource,
      boolean jmx) {
    this.name = name;
    this.errorHandler = errorHandler;
    this.transport = transport;
    this.timeSource = timeSource;
    this.dispatcher = new Dispatcher(this, name, workers);
    if (transport != null) {
      transport.attach(name, new InboundSide());
    }
    this.mbeanName = jmx ? registerMBean() : null;
  }

  Dispatcher dispatcher() {
    return dispatcher;
  }

  TimeSource timeSource() {
    return timeSource;
  }

  @Override
  public String name() {
    return name;
  }

  // ---------------------------------------------------------------- objects

  @Override
  public <S> ActiveObject<S> spawn(S servant) {
    return spawn(servant, ObjectConfig.asynchronous());
  }

  @Override
  public <S> ActiveObject<S> spawn(S servant, ObjectConfig config) {
    requireNonNull(servant, "servant");
    requireNonNull(config, "config");
    if (phase.get() != RUNNING) {
      throw new IllegalStateException("runtime " + name + " is shut down; cannot spawn " + servant);
    }
    Core<S> core = objects.add(id -> new Core<>(this, id, servant, config));
    if (phase.get() != RUNNING) {
      // A shutdown began while this object was being added; it may have missed it.
      core.stop();
      throw new IllegalStateException("runtime " + name + " is shut down; cannot spawn " + servant);
    }
    if (config.clock() instanceof ClockSupport.Owner owner) {
      clocks.add(owner.support());
      owner.support().register(core);
    }
    return core;
  }

  void unregister(Core<?> core) {
    objects.remove(core);
  }

  @Override
  @SuppressWarnings("unchecked")
  public <S> ActiveRef<S> ref(Address address) {
    requireNonNull(address, "address");
    if (address.runtime().equals(name)) {
      Core<?> core = objects.get(address.id());
      if (core == null) {
        throw new ObjectStoppedException(address);
      }
      Transport t = transport;
      return t != null && t.routesLocalEvents()
          ? new RemoteRef<>(address, t, (Core<S>) core)
          : (ActiveRef<S>) core;
    }
    Transport t = transport;
    if (t == null) {
      throw new IllegalArgumentException(
          "address "
              + address
              + " names runtime '"
              + address.runtime()
              + "' but runtime '"
              + name
              + "' has no transport; give one to ActiveRuntime.builder().transport(...)");
    }
    return new RemoteRef<>(address, t, null);
  }

  /** Where the transport hands this runtime's inbound events and requests. */
  private final class InboundSide implements Transport.Inbound {
    @Override
    public void deliver(Address destination, Event event) {
      Core<?> core = target(destination);
      boolean was = Dispatcher.enterInbound();
      try {
        core.send(event);
      } finally {
        Dispatcher.leaveInbound(was);
      }
    }

    @Override
    public <R extends @Nullable Object> FutureValue<R> ask(
        Address destination, Request<R> request) {
      Core<?> core = target(destination);
      boolean was = Dispatcher.enterInbound();
      try {
        return Requests.ask(core, request);
      } finally {
        Dispatcher.leaveInbound(was);
      }
    }

    @Override
    public <R extends @Nullable Object> void ask(
        Address destination,
        Request<R> request,
        BiConsumer<? super @Nullable R, ? super @Nullable Throwable> answer) {
      Core<?> core = target(destination);
      boolean was = Dispatcher.enterInbound();
      try {
        Requests.ask(core, request, answer);
      } finally {
        Dispatcher.leaveInbound(was);
      }
    }

    @Override
    public void lost(String route, long messages) {
      try {
        errorHandler.onLost(name, route, messages);
      } catch (RuntimeException e) {
        LOG.error("error handler of runtime {} threw", name, e);
      }
    }

    private Core<?> target(Address destination) {
      Core<?> core = objects.get(destination.id());
      if (core == null) {
        rejected.increment();
        throw new ObjectStoppedException(destination);
      }
      return core;
    }
  }

  // ---------------------------------------------------------------- counters

  void countProcessed(Carrier carrier, int n) {
    if (n > 0) {
      dispatcher.countProcessed(carrier, n);
    }
  }

  void countDropped() {
    dropped.increment();
  }

  void countRejected() {
    rejected.increment();
  }

  /** A failure of {@code core} on {@code event} (null: its cycle): count, handler, listener. */
  void reportFailure(Core<?> core, @Nullable Event event, Throwable error) {
    failures.increment();
    try {
      errorHandler.onError(core.address(), event, error);
    } catch (RuntimeException e) {
      LOG.error("error handler of runtime {} threw", name, e);
    }
    try {
      core.config().listener().onFailed(core.address(), event, error);
    } catch (RuntimeException e) {
      LOG.error("listener of {} threw", core.address(), e);
    }
  }

  @Override
  public RuntimeStats stats() {
    long[] depth = new long[2];
    objects.forEach(
        c -> {
          int d = c.queueDepth();
          depth[0] += d;
          depth[1] = Math.max(depth[1], d);
        });
    long queued = depth[0];
    long max = depth[1];
    long overruns = 0;
    for (ClockSupport c : clocks) {
      overruns += c.overruns();
    }
    return new RuntimeStats(
        objects.size(),
        queued,
        max,
        dispatcher.processed(),
        dropped.sum(),
        rejected.sum(),
        failures.sum(),
        overruns,
        transport != null ? transport.stats() : TransportStats.NONE);
  }

  // ---------------------------------------------------------------- shutdown

  @Override
  public boolean shutdown(ShutdownMode mode, Duration timeout) {
    requireNonNull(mode, "mode");
    requireNonNull(timeout, "timeout");
    if (timeout.isNegative()) {
      throw new IllegalArgumentException("timeout must be >= 0, was " + timeout);
    }
    if (!phase.compareAndSet(RUNNING, STOPPING)) {
      return cleanShutdown;
    }
    long deadline = timeSource.nanoTime() + timeout.toNanos();
    boolean clean = true;
    if (mode == ShutdownMode.DRAIN) {
      clean = dispatcher.awaitQuiet(deadline) && stats().queuedEvents() == 0;
    }
    objects.forEach(Core::stop);
    if (mode == ShutdownMode.CANCEL) {
      dispatcher.interruptRunning();
    }
    clean &= dispatcher.awaitQuiet(deadline);
    dispatcher.terminate(deadline);
    if (transport != null) {
      transport.detach(name);
    }
    unregisterMBean();
    cleanShutdown = clean;
    phase.set(TERMINATED);
    return clean;
  }

  @Override
  public void close() {
    shutdown(ShutdownMode.DRAIN, Duration.ofSeconds(10));
  }

  // ---------------------------------------------------------------- JMX

  private @Nullable ObjectName registerMBean() {
    try {
      ObjectName on =
          new ObjectName("org.armgals:type=ActiveRuntime,name=" + ObjectName.quote(name));
      ManagementFactory.getPlatformMBeanServer()
          .registerMBean(new StandardMBean(new Figures(), ActiveRuntimeMXBean.class, true), on);
      return on;
    } catch (JMException e) {
      LOG.warn("runtime {}: its MBean could not be registered; figures stay in stats()", name, e);
      return null;
    }
  }

  private void unregisterMBean() {
    ObjectName on = mbeanName;
    if (on != null) {
      try {
        ManagementFactory.getPlatformMBeanServer().unregisterMBean(on);
      } catch (JMException e) {
        LOG.warn("runtime {}: its MBean could not be unregistered", name, e);
      }
    }
  }

  /** The MBean: reads {@link #stats()}. */
  private final class Figures implements ActiveRuntimeMXBean {
    @Override
    public String getName() {
      return name;
    }

    @Override
    public long getObjects() {
      return stats().objects();
    }

    @Override
    public long getQueuedEvents() {
      return stats().queuedEvents();
    }

    @Override
    public long getMaxQueueDepth() {
      return stats().maxQueueDepth();
    }

    @Override
    public long getProcessed() {
      return dispatcher.processed();
    }

    @Override
    public long getDropped() {
      return dropped.sum();
    }

    @Override
    public long getRejected() {
      return rejected.sum();
    }

    @Override
    public long getFailures() {
      return failures.sum();
    }

    @Override
    public long getOverruns() {
      return stats().overruns();
    }

    @Override
    public long getTransportSent() {
      return transportStats().sent();
    }

    @Override
    public long getTransportReceived() {
      return transportStats().received();
    }

    @Override
    public long getTransportBatches() {
      return transportStats().batches();
    }

    @Override
    public long getTransportRejected() {
      return transportStats().rejected();
    }

    @Override
    public long getTransportLost() {
      return transportStats().lost();
    }

    @Override
    public long getTransportUnsent() {
      return transportStats().unsent();
    }

    private TransportStats transportStats() {
      Transport t = transport;
      return t != null ? t.stats() : TransportStats.NONE;
    }

    @Override
    public int getWorkers() {
      return dispatcher.liveWorkers();
    }
  }

  @Override
  public String toString() {
    return "ActiveRuntime[" + name + "]";
  }
}

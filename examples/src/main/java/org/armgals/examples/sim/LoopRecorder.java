package org.armgals.examples.sim;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongSupplier;
import org.armgals.active.Address;
import org.armgals.active.TimeSource;
import org.armgals.kernel.AdaptationRequest;
import org.armgals.kernel.Notification;
import org.armgals.kernel.ReflectionEvent;
import org.armgals.kernel.spi.ReflectionListener;
import org.armgals.maam.RobotKind;
import org.jspecify.annotations.Nullable;

/**
 * Records a run's reflective loop (paper figure 8) from what the kernel tells ({@link
 * ReflectionEvent}): on the robots' side the notifications they send and the requests they apply or
 * refuse, at the simulation's cycle; on the meta's side what it receives and lets through its
 * filter, its filter changes, its requests and what its damping held back, at the cycle of the base
 * level's time they were decided on. Each record is a map of names and simple values, nothing of a
 * JVM (no address, no clock reading of its own), so that the record of a run in lock step is the
 * same whatever the threads and wherever the meta runs ({@link #merge}).
 *
 * <p>Threading: {@link #on} on the kernel's threads, the rest on any thread.
 */
final class LoopRecorder implements ReflectionListener {
  /** The robots' side of the loop. */
  static final int BASE = 0;

  /** The meta's side. */
  static final int META = 1;

  private final long periodNanos;
  private final @Nullable LongSupplier simCycle;
  private final AtomicLong order = new AtomicLong();
  private final AtomicLong overruns = new AtomicLong();
  private final TimeSource wall;
  private final Map<String, Long> notifiedAt = new java.util.concurrent.ConcurrentHashMap<>();
  private final Map<String, Long> appliedAt = new java.util.concurrent.ConcurrentHashMap<>();
  private final ConcurrentLinkedQueue<Line> lines = new ConcurrentLinkedQueue<>();
  private final ConcurrentLinkedQueue<ReflectionEvent.Applied> applied =
      new ConcurrentLinkedQueue<>();
  private final java.util.Set<String> robots = java.util.concurrent.ConcurrentHashMap.newKeySet();
  private final java.util.Set<String> metas = java.util.concurrent.ConcurrentHashMap.newKeySet();
  private volatile @Nullable Address ignored;
  private final Map<String, Long> answered = new java.util.concurrent.ConcurrentHashMap<>();
  private volatile java.util.function.Consumer<Line> tap = line -> {};

  /**
   * One record, placed by its cycle, its side, the meta-entity it is of (empty on the robots' side)
   * and the order it came in among those.
   */
  record Line(long cycle, int side, String group, long order, Map<String, Object> fields) {}

  /**
   * @param periodNanos the control period: a time of the base level's clock falls in cycle {@code
   *     nanoTime / periodNanos}
   * @param simCycle the simulation's cycle now, for the robots' side; null in a JVM of metas only
   * @param wall real time, for the latencies from a notification to the request decided on it being
   *     applied (kept apart from the record: it differs run to run)
   */
  LoopRecorder(long periodNanos, @Nullable LongSupplier simCycle, TimeSource wall) {
    if (periodNanos <= 0) {
      throw new IllegalArgumentException("period must be positive, was " + periodNanos + " ns");
    }
    this.periodNanos = periodNanos;
    this.simCycle = simCycle;
    this.wall = requireNonNull(wall, "wall");
  }

  /**
   * The real time, in nanoseconds, from each notification a request was decided on to the request
   * being applied, for the requests of {@code loop} (the merged record, with the meta's side) that
   * were applied here; in the order of the record.
   */
  List<Long> latencies(List<Map<String, Object>> loop) {
    List<Long> latencies = new ArrayList<>();
    for (Map<String, Object> r : loop) {
      if ("requested".equals(r.get("event")) && r.get("cause") instanceof String cause) {
        Long from = notifiedAt.get(cause);
        Long to = appliedAt.get(r.get("robot") + "#" + r.get("version"));
        if (from != null && to != null) {
          latencies.add(to - from);
        }
      }
    }
    return latencies;
  }

  /**
   * Records the loop of the robot named {@code robot}, on its side; the loops of other entities
   * (the kernel's own) are ignored.
   */
  void watch(String robot) {
    robots.add(requireNonNull(robot, "robot"));
  }

  /** Records the meta side of the meta-entity named {@code meta}; other metas' are ignored. */
  void watchMeta(String meta) {
    metas.add(requireNonNull(meta, "meta"));
  }

  /**
   * Ignores the notifications sent to {@code meta}: the kernel's basic meta, which holds a robot
   * until its meta of another runtime takes it, so that the record is the same wherever the meta
   * runs.
   */
  void ignore(Address meta) {
    this.ignored = requireNonNull(meta, "meta");
  }

  @Override
  public void on(ReflectionEvent event) {
    if (!robots.contains(event.entity()) || !metaWatched(event)) {
      return;
    }
    switch (event) {
      case ReflectionEvent.Notified n -> {
        if (!n.notification().destination().equals(ignored)) {
          notifiedAt.put(n.entity() + "#" + n.notification().seq(), wall.nanoTime());
          base(n.entity(), "notified", "kind", n.notification().kind(), null, null);
        }
      }
      case ReflectionEvent.Received r -> {
        Map<String, Object> f = fields(r.entity(), "received");
        f.put("kind", r.notification().kind());
        f.put("passed", r.passed());
        meta(r.meta(), cycleOf(r.notification()), f);
      }
      case ReflectionEvent.FilterChanged c -> {
        Map<String, Object> f = fields(c.entity(), "filter");
        f.put("selector", c.selector());
        meta(c.meta(), cycleOf(c.cause()), f);
      }
      case ReflectionEvent.Requested q -> {
        Map<String, Object> f = fields(q.entity(), "requested");
        f.put("version", q.request().version());
        request(f, q.request());
        f.put("held", q.held());
        if (q.cause() != null) {
          f.put("cause", q.cause().entity() + "#" + q.cause().seq());
        }
        meta(q.meta(), cycleOf(q.cause()), f);
      }
      case ReflectionEvent.Suppressed s -> {
        Map<String, Object> f = fields(s.entity(), "suppressed");
        f.put("request", RobotKind.describe(s.adaptation()));
        meta(s.meta(), cycleOf(s.cause()), f);
      }
      case ReflectionEvent.Applied a -> {
        Map<String, Object> f = fields(a.entity(), a.applied() ? "applied" : "refused");
        f.put("version", a.request().version());
        request(f, a.request());
        if (!a.applied()) {
          f.put("refusal", String.valueOf(a.refusal()));
        }
        if (a.overrun()) {
          overruns.incrementAndGet(); // real time, not in the record: it would differ run to run
        }
        add(BASE, "", simCycle(), f);
        appliedAt.put(a.entity() + "#" + a.request().version(), wall.nanoTime());
        applied.add(a);
      }
      case ReflectionEvent.Answered a -> answered.merge(a.entity(), a.instant(), Math::max);
      case ReflectionEvent.WentFree w -> base(w.entity(), "free", "reason", w.reason(), null, null);
      case ReflectionEvent.MetaLost l ->
          base(l.entity(), "meta-lost", "runtime", l.runtime(), "reason", l.reason());
    }
  }

  private boolean metaWatched(ReflectionEvent event) {
    return switch (event) {
      case ReflectionEvent.Received r -> metas.contains(r.meta());
      case ReflectionEvent.FilterChanged c -> metas.contains(c.meta());
      case ReflectionEvent.Requested q -> metas.contains(q.meta());
      case ReflectionEvent.Suppressed s -> metas.contains(s.meta());
      case ReflectionEvent.Answered a -> metas.contains(a.meta());
      default -> true;
    };
  }

  /** A meta's note about {@code robot} at the base level's time {@code nanoTime}. */
  void note(String meta, String robot, long nanoTime, String text) {
    Map<String, Object> f = fields(robot, "note");
    f.put("text", requireNonNull(text, "text"));
    meta(meta, Math.floorDiv(nanoTime, periodNanos), f);
  }

  /**
   * Waits until the metas have answered, in lock step, the barrier of each robot's instant that
   * {@code instants} names (its last), at most {@code timeout}: then they have handled everything
   * the robots sent.
   *
   * @return whether they all had
   */
  boolean awaitAnswered(Map<String, Long> instants, java.time.Duration timeout) {
    long deadline = System.nanoTime() + timeout.toNanos();
    for (Map.Entry<String, Long> e : instants.entrySet()) {
      while (answered.getOrDefault(e.getKey(), -1L) < e.getValue()) {
        if (System.nanoTime() > deadline) {
          return false;
        }
        java.util.concurrent.locks.LockSupport.parkNanos(1_000_000L);
      }
    }
    return true;
  }

  /** How many adaptation points of the robots overran their cycle's time budget. */
  long overruns() {
    return overruns.get();
  }

  /** The requests applied or refused since the last call, in the order they were. */
  List<ReflectionEvent.Applied> drainApplied() {
    List<ReflectionEvent.Applied> drained = new ArrayList<>();
    ReflectionEvent.Applied a;
    while ((a = applied.poll()) != null) {
      drained.add(a);
    }
    return drained;
  }

  /** What it recorded so far, in the order it came. */
  List<Line> lines() {
    return List.copyOf(lines);
  }

  /**
   * Puts records of both sides on one time line: by cycle, the robots' side first, then each meta's
   * records in the order that meta made them (one meta's records come from its one object). The
   * order of the result depends only on the records, not on when they were made.
   */
  static List<Map<String, Object>> merge(List<Line> records) {
    List<Line> sorted = new ArrayList<>(records);
    sorted.sort(
        Comparator.comparingLong(Line::cycle)
            .thenComparingInt(Line::side)
            .thenComparing(Line::group)
            .thenComparingLong(Line::order));
    List<Map<String, Object>> merged = new ArrayList<>();
    for (Line l : sorted) {
      Map<String, Object> m = new LinkedHashMap<>();
      m.put("cycle", l.cycle());
      m.putAll(l.fields());
      merged.add(m);
    }
    return merged;
  }

  /** A record read back from a file: its side is that of its fields, its order the file's. */
  static Line read(Map<?, ?> record, long order) {
    Map<String, Object> fields = new LinkedHashMap<>();
    record.forEach(
        (k, v) -> {
          if (!"cycle".equals(k)) {
            fields.put(String.valueOf(k), simple(v));
          }
        });
    long cycle = ((Number) requireNonNull(record.get("cycle"), "cycle")).longValue();
    Object meta = fields.get("meta");
    return new Line(
        cycle, meta == null ? BASE : META, meta == null ? "" : meta.toString(), order, fields);
  }

  /**
   * A value read back from JSON as the record had it: a number written without a fraction or an
   * exponent a long (as {@link LoopJson} writes one), any other a double, {@code 0.0} included.
   */
  private static @Nullable Object simple(@Nullable Object v) {
    return switch (v) {
      case null -> null;
      case java.math.BigDecimal d -> number(d);
      case Map<?, ?> m -> {
        Map<String, Object> copy = new LinkedHashMap<>();
        m.forEach((k, x) -> copy.put(String.valueOf(k), simple(x)));
        yield copy;
      }
      case List<?> l -> l.stream().map(LoopRecorder::simple).toList();
      default -> v;
    };
  }

  private static Object number(java.math.BigDecimal d) {
    if (d.scale() != 0) {
      return d.doubleValue();
    }
    try {
      return d.longValueExact();
    } catch (ArithmeticException tooLong) {
      return d.doubleValue();
    }
  }

  private static void request(Map<String, Object> f, AdaptationRequest request) {
    f.put("request", RobotKind.describe(request.adaptation()));
    RobotKind.reason(request.adaptation()).ifPresent(why -> f.put("reason", why));
    if (request.adaptation() instanceof org.armgals.kernel.Adaptation.ApplyBehavior b) {
      f.put("behavior", b.behavior());
      if (b.input() != null) {
        f.put("input", sorted(b.input()));
      }
    }
  }

  /** {@code value} with its maps' keys in order: the same request reads the same on every run. */
  private static Object sorted(Object value) {
    return switch (value) {
      case Map<?, ?> m -> {
        java.util.TreeMap<String, Object> t = new java.util.TreeMap<>();
        m.forEach((k, v) -> t.put(String.valueOf(k), v == null ? null : sorted(v)));
        yield t;
      }
      case List<?> l -> l.stream().map(v -> v == null ? null : sorted(v)).toList();
      default -> value;
    };
  }

  private void base(
      String robot, String event, String k1, Object v1, @Nullable String k2, @Nullable Object v2) {
    Map<String, Object> f = fields(robot, event);
    f.put(k1, v1);
    if (k2 != null && v2 != null) {
      f.put(k2, v2);
    }
    add(BASE, "", simCycle(), f);
  }

  private void meta(String meta, long cycle, Map<String, Object> f) {
    Map<String, Object> m = new LinkedHashMap<>();
    m.put("meta", meta);
    m.putAll(f);
    add(META, meta, cycle, m);
  }

  private static Map<String, Object> fields(String robot, String event) {
    Map<String, Object> f = new LinkedHashMap<>();
    f.put("event", event);
    f.put("robot", robot);
    return f;
  }

  private void add(int side, String group, long cycle, Map<String, Object> fields) {
    Line line = new Line(cycle, side, group, order.incrementAndGet(), fields);
    lines.add(line);
    tap.accept(line);
  }

  /** Tells {@code tap} each record from now on as it is made, on the thread that makes it. */
  void tap(java.util.function.Consumer<Line> tap) {
    requireNonNull(tap, "tap");
    lines.forEach(tap); // those before the first cycle: the metas' first filters
    this.tap = tap;
  }

  private long simCycle() {
    return simCycle == null ? -1 : simCycle.getAsLong();
  }

  private long cycleOf(Notification n) {
    return Math.floorDiv(n.nanoTime(), periodNanos);
  }

  /** The cycle of a cause; -1 (before the run) for what was done from outside a policy. */
  private long cycleOf(ReflectionEvent.@Nullable Cause cause) {
    return cause == null ? -1 : Math.floorDiv(cause.nanoTime(), periodNanos);
  }
}

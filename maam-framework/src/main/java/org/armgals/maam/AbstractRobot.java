package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentLinkedQueue;
import org.armgals.active.TimeSource;
import org.armgals.gals.CycleContext;
import org.armgals.gals.Island;
import org.armgals.gals.ReactiveEntity;
import org.armgals.kernel.AdaptationPoint;
import org.armgals.kernel.BehavioralMeta;
import org.armgals.kernel.Entity;
import org.armgals.kernel.EntityOptions;
import org.armgals.kernel.Stimulus;
import org.armgals.kernel.StructuralMeta;
import org.armgals.kernel.spi.InstantContext;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.RobotErrorHandler;
import org.armgals.representation.p.PState;
import org.jspecify.annotations.Nullable;

/**
 * A robot (paper §5.4, step 4: the programmer's {@code Robot} extends this class and registers its
 * schemas, modules and connectors in its constructor). Each {@link #cycle} runs every behavior
 * module once in the order of the schedule its {@link MetaRobot} computed, then tells the body the
 * cycle ended, notifies the {@link BMetaRobot} if there is one, and applies the requested
 * adaptations at its {@link AdaptationPoint}.
 *
 * <p>A cycle is a method: tests and simulators call {@link #cycle} by hand; {@link #start} makes
 * the robot a reactive entity of an arm-gals {@link Island} (paper §5.3), which runs one cycle per
 * release. On an island the island rules the cycle: its {@link Island#adaptationPoint() adaptation
 * point} replaces the robot's own, requested adaptations are applied by the island between two
 * instants (traced, and timed against its period in its {@link org.armgals.gals.IslandStats}), each
 * cycle adds a line with its emissions to the island's trace, and the robot talks to entities of
 * its own or other islands through {@link #received} and {@link #emit}.
 *
 * <p>Threading: one thread at a time runs {@link #cycle} (on an island, the release gives the
 * happens-before between two cycles and the adaptations between them). The registration methods
 * ({@link #addSchema} and the others) are for the constructor, for the thread stepping the robot
 * between cycles, or for the robot's own modules; any other thread asks through {@link #request},
 * which is thread-safe.
 */
public abstract class AbstractRobot {

  private final String name;
  private final Body body;
  private final TimeSource time;
  private final MetaRobot meta;
  private final ConcurrentLinkedQueue<Adaptation> requests = new ConcurrentLinkedQueue<>();
  private final Map<Connector, ConnectorState> connectorStates = new HashMap<>();
  private final List<Adaptation> applied = new ArrayList<>();
  private final List<CycleReport.Rejected> rejected = new ArrayList<>();
  private final List<String> failedModules = new ArrayList<>();
  private final Plan.Failures failures = this::moduleFailed;
  private final Object hosting = new Object();

  private AdaptationPoint adaptationPoint = AdaptationPoint.END_OF_CYCLE;
  private @Nullable BMetaRobot behavioralMeta;
  private RobotErrorHandler errorHandler = RobotErrorHandler.logging();
  private @Nullable Plan plan;
  private volatile @Nullable ReactiveEntity<AbstractRobot> entity;
  private @Nullable CycleContext<AbstractRobot> context;
  private volatile @Nullable Entity kernelEntity;
  private @Nullable InstantContext instant;
  private volatile @Nullable Thread cycling;
  private long planVersion = -1;
  private long cycles;
  private long errors;
  private long rejections;

  /**
   * A robot with an empty program, scheduled by {@link Scheduler#topological()}.
   *
   * @param name not blank
   * @param body what it senses and drives
   * @param time where it reads the time of each cycle (its clock, when it runs on one)
   */
  protected AbstractRobot(String name, Body body, TimeSource time) {
    this(name, body, time, MetaRobot.create(Scheduler.topological()));
  }

  /** A robot whose program is held by {@code meta}. */
  protected AbstractRobot(String name, Body body, TimeSource time, MetaRobot meta) {
    requireNonNull(name, "name");
    if (name.isBlank()) {
      throw new IllegalArgumentException("robot name '" + name + "': expected not blank");
    }
    this.name = name;
    this.body = requireNonNull(body, "body");
    this.time = requireNonNull(time, "time");
    this.meta = requireNonNull(meta, "meta");
  }

  /** Its name. */
  public final String name() {
    return name;
  }

  /** Its body. */
  public final Body body() {
    return body;
  }

  /** Its scheduling meta level. */
  public final MetaRobot metaRobot() {
    return meta;
  }

  /** The order its modules run in. */
  public final Schedule schedule() {
    return meta.schedule();
  }

  /** Adds {@code schema} after the others and reschedules. See {@link Adaptation.AddSchema}. */
  public final void addSchema(Schema schema) {
    meta.apply(new Adaptation.AddSchema(schema));
  }

  /** Removes a schema and its connectors and reschedules. See {@link Adaptation.RemoveSchema}. */
  public final void removeSchema(String schemaName) {
    meta.apply(new Adaptation.RemoveSchema(schemaName));
  }

  /**
   * Adds {@code module} alone in a schema of its name: modules added this way are joined by
   * connectors.
   */
  public final void addBehaviorModule(BehaviorModule module) {
    requireNonNull(module, "module");
    addSchema(Schema.builder(module.name()).add(module).build());
  }

  /** Adds a connector and reschedules. See {@link Adaptation.AddConnector}. */
  public final void addConnector(Connector connector) {
    meta.apply(new Adaptation.AddConnector(connector));
  }

  /** Removes a connector and reschedules. See {@link Adaptation.RemoveConnector}. */
  public final void removeConnector(Connector connector) {
    meta.apply(new Adaptation.RemoveConnector(connector));
  }

  /** Replaces the whole program. See {@link Adaptation.SetScheduling}. */
  public final void setScheduling(List<Schema> schemas, List<Connector> connectors) {
    meta.apply(new Adaptation.SetScheduling(schemas, connectors));
  }

  /**
   * Replaces one module by another of the same name and shape. See {@link Adaptation.ChangeModule}.
   */
  public final void changeModule(BehaviorModule replacement) {
    meta.apply(new Adaptation.ChangeModule(replacement));
  }

  /**
   * Where in the cycle requested adaptations are applied: {@link AdaptationPoint#END_OF_CYCLE} by
   * default; on an island, the island's.
   */
  public final AdaptationPoint adaptationPoint() {
    ReactiveEntity<AbstractRobot> e = entity;
    return e == null ? adaptationPoint : e.island().adaptationPoint();
  }

  /**
   * Sets where in the cycle requested adaptations are applied when the robot is stepped by hand.
   *
   * @param point {@link AdaptationPoint#BEGIN_OF_CYCLE} or {@link AdaptationPoint#END_OF_CYCLE}: a
   *     robot adapts only between cycles
   * @throws IllegalArgumentException {@link AdaptationPoint#ON_ARRIVAL}
   * @throws IllegalStateException the robot runs on an island, whose point rules
   */
  protected final void setAdaptationPoint(AdaptationPoint point) {
    requireNonNull(point, "point");
    if (point == AdaptationPoint.ON_ARRIVAL) {
      throw new IllegalArgumentException(
          "adaptation point of robot "
              + name
              + " must be BEGIN_OF_CYCLE or END_OF_CYCLE, was "
              + point);
    }
    ReactiveEntity<AbstractRobot> e = entity;
    if (e != null) {
      throw new IllegalStateException(
          "robot "
              + name
              + " runs on island "
              + e.island().name()
              + ", whose adaptation point rules");
    }
    this.adaptationPoint = point;
  }

  /** Sets the behavioral meta notified at the end of each cycle. */
  protected final void setBehavioralMeta(BMetaRobot behavioralMeta) {
    this.behavioralMeta = requireNonNull(behavioralMeta, "behavioralMeta");
  }

  /** Sets where failures go; {@link RobotErrorHandler#logging()} by default. */
  protected final void setErrorHandler(RobotErrorHandler errorHandler) {
    this.errorHandler = requireNonNull(errorHandler, "errorHandler");
  }

  /**
   * Asks for {@code adaptation}, applied at the next {@link AdaptationPoint}: at the beginning of
   * the next cycle, or at the end of the current or next one. Any thread; requests are applied in
   * the order they were made. On an island it is an adaptation request of the robot's entity
   * ({@link ReactiveEntity#adapt}); requests made before {@link #start} go to the island then.
   */
  public final void request(Adaptation adaptation) {
    requireNonNull(adaptation, "adaptation");
    synchronized (hosting) {
      ReactiveEntity<AbstractRobot> e = entity;
      if (e == null) {
        requests.add(adaptation);
      } else {
        IslandHost.request(e, adaptation);
      }
    }
  }

  /**
   * One cycle, by hand: adaptations if at the beginning, every module in schedule order, {@link
   * Body#endCycle}, the behavioral meta's notification, adaptations if at the end.
   *
   * @throws IllegalStateException the robot runs on an island, which releases its cycles
   */
  public final void cycle() {
    ReactiveEntity<AbstractRobot> e = entity;
    if (e != null) {
      throw new IllegalStateException(
          "robot " + name + " runs on island " + e.island().name() + ", which releases its cycles");
    }
    Entity k = kernelEntity;
    if (k != null) {
      throw new IllegalStateException(
          "robot " + name + " is the kernel entity " + k + ", whose clock releases its cycles");
    }
    if (adaptationPoint == AdaptationPoint.BEGIN_OF_CYCLE) {
      adapt();
    }
    react();
    if (adaptationPoint == AdaptationPoint.END_OF_CYCLE) {
      adapt();
    }
  }

  /**
   * One cycle released by the robot's island: the reaction of its entity. The island applies the
   * adaptations; the cycle's emissions (and the adaptations it saw rejected) go to its trace.
   */
  final void islandCycle(CycleContext<AbstractRobot> cycle) {
    context = cycle;
    try {
      boolean tracing = cycle.tracing();
      if (tracing) {
        for (CycleReport.Rejected r : rejected) {
          cycle.trace("rejected " + IslandHost.describe(r.adaptation()) + ": " + r.reason());
        }
      }
      Plan current = react();
      if (tracing) {
        cycle.trace("cycle " + cycles + " " + current.emissions());
      }
    } finally {
      context = null;
    }
  }

  /**
   * The payloads the robot's entity took at this release, ordered as {@link CycleContext#inputs()};
   * empty when the robot is stepped by hand. For its modules, during a cycle.
   */
  public final List<Object> received() {
    InstantContext i = instant;
    if (i != null) {
      List<Object> inputs = new ArrayList<>();
      for (Stimulus s : i.stimuli()) {
        inputs.add(s.input());
      }
      return inputs;
    }
    CycleContext<AbstractRobot> c = context;
    return c == null ? List.of() : c.inputs();
  }

  /**
   * What the robot shows of itself each cycle (paper §3.2: its state, as the procedural
   * representation reifies it), in the values a notification can carry (strings, booleans, boxed
   * numbers, lists of those): {@code cycle} (the cycles run), {@code program} (the version of its
   * program: it moves at each adaptation applied) and {@code errors}. A robot adds its readings,
   * the outputs of its modules, its energy: override, call this one, and add to its map. Each cycle
   * must give the same names with values of the same types. Called on the robot's thread, at the
   * end of each cycle.
   */
  protected Map<String, Object> observe() {
    Map<String, Object> m = new LinkedHashMap<>();
    m.put("cycle", cycles);
    m.put("program", meta.version());
    m.put("errors", errors);
    return m;
  }

  /** {@link #observe()} as a state of the robot's {@link RobotKind}. */
  public final PState observation() {
    return new PState(observe());
  }

  /**
   * Makes this robot a kernel entity of {@code kind} in the synchronous mode on {@code island}
   * (paper figure 8): its cycle is the entity's program, run at each of the island's releases; each
   * cycle ends with the kind's {@link RobotKind#CYCLE} behavior applied with {@link #observe()}, so
   * {@code meta} is notified of it as {@code options}' notification policy says, on its own object,
   * never on the robot's thread; the kernel's adaptation requests for the robot ({@link
   * RobotKind#request}) are applied to its program at the island's adaptation point and
   * acknowledged, applied or refused. In lock step ({@link EntityOptions#withLockStep}, with the
   * island on a manual clock), the request decided on the notifications of cycle {@code n} is
   * applied at the adaptation point of cycle {@code n + k}.
   *
   * @param kind a kind made by {@link RobotKind#define} for this robot's observation
   * @param options the notification policy and the lock step; the island sets the rest
   * @return the robot's entity
   * @throws IllegalStateException the robot already runs
   */
  public final Entity start(
      Island island, StructuralMeta<PState> kind, BehavioralMeta meta, EntityOptions options) {
    requireNonNull(island, "island");
    requireNonNull(kind, "kind");
    requireNonNull(meta, "meta");
    requireNonNull(options, "options");
    synchronized (hosting) {
      if (entity != null || kernelEntity != null) {
        throw new IllegalStateException("robot " + name + " already runs");
      }
      Entity e = island.spawn(kind, name, meta, options.withProgram(new KernelHost(this)));
      kernelEntity = e;
      return e;
    }
  }

  /**
   * The kernel entity the robot is, once {@linkplain #start(Island, StructuralMeta, BehavioralMeta,
   * EntityOptions) started} as one.
   */
  public final Optional<Entity> kernelEntity() {
    return Optional.ofNullable(kernelEntity);
  }

  /** One cycle as the program of its kernel entity: the modules, then the reified cycle. */
  final void kernelCycle(InstantContext now) {
    instant = now;
    cycling = Thread.currentThread();
    try {
      react();
      now.apply(RobotKind.CYCLE, observe());
    } finally {
      cycling = null;
      instant = null;
    }
  }

  /** Whether the calling thread is inside one of this robot's cycles as a kernel entity. */
  final boolean inCycle() {
    return cycling == Thread.currentThread();
  }

  /**
   * Applies {@code change} to the program, at the kernel entity's adaptation point.
   *
   * @throws IllegalArgumentException the program refuses it; nothing changed
   */
  final void applyOrRefuse(Adaptation change) {
    long before = meta.version();
    meta.apply(change);
    if (change instanceof Adaptation.ChangeModule c && plan != null && planVersion == before) {
      plan.replace(c.replacement());
      planVersion = meta.version();
    }
    applied.add(change);
    adapted(change);
  }

  /**
   * The robot's catalog of modules: builds the module named {@code name} with {@code parameters},
   * for a {@link RobotKind#changeModule(String, Map)} request, which names a module instead of
   * carrying one (a meta in another runtime cannot send code). On the robot's thread, at its
   * adaptation point. The default has no catalog.
   *
   * @throws IllegalArgumentException no module of that name, or parameters it cannot take: the
   *     request is refused and the meta told why
   */
  protected BehaviorModule module(String name, Map<String, Object> parameters) {
    throw new IllegalArgumentException(
        "robot " + this.name + " has no catalog of modules; cannot build '" + name + "'");
  }

  /**
   * Called after {@code change}, requested by the robot's meta through the kernel, was applied to
   * its program: on the robot's thread, at its adaptation point, so whatever it records is in step
   * with the cycles (a run's journal, say). Does nothing by default.
   */
  protected void adapted(Adaptation change) {}

  /**
   * The signals emitted in the last cycle, after suppression, in slot order; for {@link
   * #observe()}.
   */
  protected final List<CycleReport.Emission> emissions() {
    Plan current = plan;
    return current == null ? List.of() : current.emissions();
  }

  /**
   * Sends {@code payload} to {@code target}, a reactive entity (another robot's, or any other) of
   * this island or another: it takes it at its next release (see {@link CycleContext#emit}). For
   * the robot's modules, during a cycle on an island.
   *
   * @throws IllegalStateException not during a cycle of the robot on an island
   */
  public final void emit(ReactiveEntity<?> target, Object payload) {
    requireNonNull(target, "target");
    requireNonNull(payload, "payload");
    CycleContext<AbstractRobot> c = context;
    if (c == null) {
      throw new IllegalStateException(
          "robot " + name + " emits only during one of its cycles on an island");
    }
    c.emit(target, payload);
  }

  /** Every module in schedule order, the body's end of cycle, the behavioral meta. */
  private Plan react() {
    long number = ++cycles;
    long now = time.nanoTime();
    Plan current = plan();
    current.run(number, now, body, failures);
    body.endCycle();
    BMetaRobot bmeta = behavioralMeta;
    if (bmeta != null) {
      notify(
          bmeta,
          new CycleReport(
              name, number, now, current.emissions(), applied, rejected, failedModules));
    }
    applied.clear();
    rejected.clear();
    failedModules.clear();
    return current;
  }

  /**
   * Makes this robot a reactive entity of {@code island}, named as the robot, with one reaction
   * that runs a cycle: from the island's next release, one cycle per release. The robot is then no
   * longer stepped by hand; closing the island stops it.
   *
   * @return its entity: send it events, query its state, or name it as the target of another
   *     robot's {@link #emit}
   * @throws IllegalStateException the robot already runs on an island, or {@code island} is closed
   * @throws IllegalArgumentException the island has an entity of the robot's name
   */
  public final ReactiveEntity<AbstractRobot> start(Island island) {
    requireNonNull(island, "island");
    synchronized (hosting) {
      ReactiveEntity<AbstractRobot> e = entity;
      if (e != null) {
        throw new IllegalStateException(
            "robot " + name + " already runs on island " + e.island().name());
      }
      e = IslandHost.start(this, island);
      Adaptation next;
      while ((next = requests.poll()) != null) {
        IslandHost.request(e, next);
      }
      entity = e;
      return e;
    }
  }

  /** The cycles run so far. */
  public final long cycles() {
    return cycles;
  }

  /** The failures so far: modules' steps and the behavioral meta's notifications. */
  public final long errors() {
    return errors;
  }

  /** The adaptations rejected so far. */
  public final long rejectedAdaptations() {
    return rejections;
  }

  private void notify(BMetaRobot bmeta, CycleReport report) {
    try {
      bmeta.onCycle(report, this::request);
    } catch (Exception e) {
      errors++;
      errorHandler.onError(name, "bmeta", e);
    }
  }

  private void adapt() {
    Adaptation next;
    while ((next = requests.poll()) != null) {
      apply(next);
    }
  }

  /**
   * Applies one requested adaptation, or records its rejection for the next {@link CycleReport}.
   * Between cycles, on the thread that steps the robot (on an island: the island's).
   */
  final void apply(Adaptation next) {
    try {
      long before = meta.version();
      meta.apply(next);
      if (next instanceof Adaptation.ChangeModule change && plan != null && planVersion == before) {
        plan.replace(change.replacement());
        planVersion = meta.version();
      }
      applied.add(next);
    } catch (IllegalArgumentException e) {
      rejections++;
      rejected.add(new CycleReport.Rejected(next, String.valueOf(e.getMessage())));
      errorHandler.onError(name, "adaptation " + next, e);
    }
  }

  private Plan plan() {
    Plan current = plan;
    if (current == null || planVersion != meta.version()) {
      connectorStates.keySet().retainAll(new java.util.HashSet<>(meta.connectors()));
      current =
          new Plan(
              meta.schedule(),
              meta.schemas(),
              meta.connectors(),
              c -> connectorStates.computeIfAbsent(c, k -> new ConnectorState()));
      plan = current;
      planVersion = meta.version();
    }
    return current;
  }

  private void moduleFailed(BehaviorModule module, Exception error) {
    errors++;
    failedModules.add(module.name());
    errorHandler.onError(name, module.name(), error);
  }
}

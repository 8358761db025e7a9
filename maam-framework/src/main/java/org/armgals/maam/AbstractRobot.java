package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.armgals.active.Address;
import org.armgals.active.FutureValue;
import org.armgals.active.TimeSource;
import org.armgals.gals.Island;
import org.armgals.kernel.Adaptation;
import org.armgals.kernel.BehavioralMeta;
import org.armgals.kernel.Entity;
import org.armgals.kernel.EntityOptions;
import org.armgals.kernel.NotificationPolicy;
import org.armgals.kernel.Stimulus;
import org.armgals.kernel.StructuralMeta;
import org.armgals.kernel.spi.InstantContext;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.RobotErrorHandler;
import org.armgals.representation.Behavior;
import org.armgals.representation.Behaviors;
import org.armgals.representation.State;
import org.armgals.representation.p.PState;
import org.jspecify.annotations.Nullable;

/**
 * A robot (paper §5.4, figure 8): the programmer's {@code Robot} extends this class and registers
 * its schemas, modules and connectors in its constructor (step 4 of the paper's list). Each {@link
 * #cycle} runs every behavior module once, in the order of the schedule its {@link MetaRobot}
 * computed, then tells the body the cycle ended.
 *
 * <p><b>A robot is a kernel entity.</b> {@link #start} makes it an entity of the ARM kernel in the
 * synchronous mode, released by an arm-gals {@link Island} (its kind: a {@link RobotKind}): its
 * cycle is the entity's program, each cycle ends with the kind's {@value RobotKind#CYCLE} behavior
 * applied with what the robot {@link #observe() observes} of itself, and its behavioral meta-entity
 * (a {@link BMetaRobot}, or any kernel {@link BehavioralMeta}) is notified of it as the entity's
 * {@link NotificationPolicy} says, on its own object, never on the robot's thread: in the same JVM
 * or in another one, over the broker. The meta's requests ({@link RobotKind}) are versioned,
 * damped, applied at the island's adaptation point and acknowledged, applied or refused; in lock
 * step ({@link EntityOptions#withLockStep}) the request decided on cycle {@code n} is applied at
 * the adaptation point of cycle {@code n + k}, so that runs on virtual time are reproducible. From
 * then on the robot is the entity: it implements {@link Entity} by forwarding to it.
 *
 * <p>Stepped by hand ({@link #cycle}, for tests and simulations of modules), a robot has no meta
 * level; its program changes only through the registration methods, between cycles.
 *
 * <p>Threading: one thread at a time runs {@link #cycle} (as an entity, its object: the releases
 * give the happens-before between two cycles and the adaptations between them). The registration
 * methods are for the constructor, or for the thread stepping the robot by hand between cycles; the
 * {@link Entity} methods for any thread once it is started.
 */
public abstract class AbstractRobot implements Entity {

  private final String name;
  private final Body body;
  private final TimeSource time;
  private final MetaRobotImpl program;
  private final Map<Connector, ConnectorState> connectorStates = new HashMap<>();
  private final Plan.Failures failures = this::moduleFailed;
  private final Object hosting = new Object();
  private final List<String> forgotten = new ArrayList<>();

  private RobotErrorHandler errorHandler = RobotErrorHandler.logging();
  private @Nullable Plan plan;
  private long planVersion = -1;
  private volatile @Nullable Entity entity;
  private volatile Behaviors<?> catalog = EMPTY;
  private @Nullable InstantContext instant;
  private volatile @Nullable Thread cycling;
  private long cycles;
  private long errors;
  private long changes;

  private static final Behaviors<?> EMPTY =
      org.armgals.representation.p.PSpace.of(new PState(Map.of())).methods();

  /**
   * A robot with an empty program, scheduled by {@link Scheduler#topological()}.
   *
   * @param name not blank; its kernel entity's name
   * @param body what it senses and drives
   * @param time where it reads the time of each cycle (its clock, when it runs on one)
   */
  protected AbstractRobot(String name, Body body, TimeSource time) {
    this(name, body, time, MetaRobot.create(Scheduler.topological()));
  }

  /** A robot whose program is held by {@code meta}, made by {@link MetaRobot#create}. */
  protected AbstractRobot(String name, Body body, TimeSource time, MetaRobot meta) {
    requireNonNull(name, "name");
    if (name.isBlank()) {
      throw new IllegalArgumentException("robot name '" + name + "': expected not blank");
    }
    this.name = name;
    this.body = requireNonNull(body, "body");
    this.time = requireNonNull(time, "time");
    this.program = (MetaRobotImpl) requireNonNull(meta, "meta");
  }

  /** Its name, which is its kernel entity's. */
  @Override
  public final String name() {
    return name;
  }

  /** Its body. */
  public final Body body() {
    return body;
  }

  /** Its scheduling meta level, which holds its program. */
  public final MetaRobot metaRobot() {
    return program;
  }

  /** The order its modules run in. */
  public final Schedule schedule() {
    return program.schedule();
  }

  /** Adds {@code schema} after the others and reschedules. */
  public final void addSchema(Schema schema) {
    register(new ProgramChange.AddSchema(schema));
  }

  /** Removes a schema and its connectors and reschedules. */
  public final void removeSchema(String schemaName) {
    register(new ProgramChange.RemoveSchema(schemaName));
  }

  /**
   * Adds {@code module} alone in a schema of its name: modules added this way are joined by
   * connectors.
   */
  public final void addBehaviorModule(BehaviorModule module) {
    requireNonNull(module, "module");
    addSchema(Schema.builder(module.name()).add(module).build());
  }

  /** Adds a connector and reschedules. */
  public final void addConnector(Connector connector) {
    register(new ProgramChange.AddConnector(connector));
  }

  /** Removes a connector and reschedules. */
  public final void removeConnector(Connector connector) {
    register(new ProgramChange.RemoveConnector(connector));
  }

  /** Replaces the whole program. */
  public final void setScheduling(List<Schema> schemas, List<Connector> connectors) {
    register(new ProgramChange.SetScheduling(schemas, connectors));
  }

  /** Replaces one module by another of the same name and shape. */
  public final void changeModule(BehaviorModule replacement) {
    register(new ProgramChange.ChangeModule(replacement));
  }

  /** Sets where failures go; {@link RobotErrorHandler#logging()} by default. */
  protected final void setErrorHandler(RobotErrorHandler errorHandler) {
    this.errorHandler = requireNonNull(errorHandler, "errorHandler");
  }

  /** A registration: by hand, before the robot runs as an entity. */
  private void register(ProgramChange.Change change) {
    Entity e = entity;
    if (e != null) {
      throw new IllegalStateException(
          "robot "
              + name
              + " runs as a kernel entity: its program changes by its meta's requests (RobotKind),"
              + " at its adaptation point");
    }
    applyChange(change);
  }

  /**
   * One cycle, by hand: every module in schedule order, then {@link Body#endCycle}.
   *
   * @throws IllegalStateException the robot runs as a kernel entity, whose clock releases its
   *     cycles
   */
  public final void cycle() {
    Entity e = entity;
    if (e != null) {
      throw new IllegalStateException(
          "robot " + name + " is the kernel entity " + e + ", whose clock releases its cycles");
    }
    react();
  }

  /**
   * Makes this robot a kernel entity of {@code kind} in the synchronous mode on {@code island}
   * (paper figure 8), notifying {@code meta}: from the island's next release, one cycle per
   * release, then the kind's {@value RobotKind#CYCLE} behavior applied with {@link #observe()}. The
   * entity takes the robot's name.
   *
   * @param kind a kind made by {@link RobotKind} for this robot's class and observation
   * @param meta its behavioral meta: a {@link BMetaRobot}, any behavioral meta of the kind's kernel
   *     ({@code kernel.basicBehavioralMeta()} for none of its own); one in another runtime takes it
   *     later with {@link BehavioralMeta#addBaseLevelEntity}
   * @param options the notification policy and the lock step (from {@link Island#entityOptions()});
   *     the island sets the rest
   * @throws IllegalStateException the robot already runs
   * @throws IllegalArgumentException the kernel has an entity of the robot's name
   */
  public final void start(
      Island island, StructuralMeta<PState> kind, BehavioralMeta meta, EntityOptions options) {
    requireNonNull(meta, "meta");
    start(island, kind, meta, options, true);
  }

  /**
   * {@link #start(Island, StructuralMeta, BehavioralMeta, EntityOptions)} with no behavioral meta
   * yet: a meta of another runtime takes it through the broker (its {@link
   * BehavioralMeta#addBaseLevelEntity} on a handle of the robot, found by the name the robot's
   * runtime registered). Until then it notifies no one, and in lock step waits for no one.
   */
  public final void start(Island island, StructuralMeta<PState> kind, EntityOptions options) {
    start(island, kind, null, options, false);
  }

  private void start(
      Island island,
      StructuralMeta<PState> kind,
      @Nullable BehavioralMeta meta,
      EntityOptions options,
      boolean withMeta) {
    requireNonNull(island, "island");
    requireNonNull(kind, "kind");
    requireNonNull(options, "options");
    synchronized (hosting) {
      if (entity != null) {
        throw new IllegalStateException("robot " + name + " already runs");
      }
      catalog = kind.behaviors();
      EntityOptions withProgram = options.withProgram(new KernelHost(this));
      entity =
          withMeta
              ? island.spawn(kind, name, requireNonNull(meta, "meta"), withProgram)
              : island.spawn(kind, name, withProgram);
    }
  }

  /**
   * The kernel entity this robot is, once started.
   *
   * @throws IllegalStateException not started
   */
  @Override
  public final Entity handle() {
    Entity e = entity;
    if (e == null) {
      throw new IllegalStateException(
          "robot "
              + name
              + " is not started: make it a kernel entity with start(island, kind, meta, options)");
    }
    return e;
  }

  /** Whether it runs as a kernel entity. */
  public final boolean started() {
    return entity != null;
  }

  @Override
  public final Address address() {
    return handle().address();
  }

  @Override
  public final StructuralMeta<?> structuralMeta() {
    return handle().structuralMeta();
  }

  @Override
  public final Optional<BehavioralMeta> behavioralMeta() {
    return handle().behavioralMeta();
  }

  @Override
  public final State state() {
    return handle().state();
  }

  @Override
  public final NotificationPolicy notificationPolicy() {
    return handle().notificationPolicy();
  }

  @Override
  public final long appliedVersion() {
    return handle().appliedVersion();
  }

  @Override
  public final void send(String trigger, @Nullable Object input) {
    handle().send(trigger, input);
  }

  @Override
  public final FutureValue<@Nullable Object> call(String behavior, @Nullable Object input) {
    return handle().call(behavior, input);
  }

  @Override
  public final boolean isStopped() {
    Entity e = entity;
    return e != null && e.isStopped();
  }

  @Override
  public final int queueDepth() {
    return handle().queueDepth();
  }

  @Override
  public String toString() {
    Entity e = entity;
    return "robot " + name + (e == null ? "" : " (" + e.address() + ")");
  }

  /**
   * The inputs of the stimuli its entity took at this release ({@link Entity#send}), in the
   * instant's order; empty when the robot is stepped by hand. For its modules, during a cycle.
   */
  public final List<Object> received() {
    InstantContext i = instant;
    if (i == null) {
      return List.of();
    }
    List<Object> inputs = new ArrayList<>();
    for (Stimulus s : i.stimuli()) {
      inputs.add(s.input());
    }
    return inputs;
  }

  /**
   * What the robot shows of itself each cycle (paper §3.2: its state, as the procedural
   * representation reifies it), in values a notification can carry (strings, booleans, boxed
   * numbers, lists of those): {@code cycle} (the cycles run), {@code program} (the version of its
   * program: it moves at each change applied), {@code schemas} (their names, in schedule order) and
   * {@code errors}. A robot adds its readings, the outputs of its modules, its energy: override,
   * call this one, and add to its map. Each cycle must give the same names with values of the same
   * types. Called on the robot's thread, at the end of each cycle.
   */
  protected Map<String, Object> observe() {
    return RobotKind.baseObservation(
        cycles, changes, program.schemas().stream().map(Schema::name).toList(), errors);
  }

  /** {@link #observe()} as a state of the robot's {@link RobotKind}. */
  public final PState observation() {
    return new PState(observe());
  }

  /**
   * The signals emitted in the last cycle, after suppression, in slot order; for {@link
   * #observe()}.
   */
  protected final List<Emission> emissions() {
    Plan current = plan;
    return current == null ? List.of() : current.emissions();
  }

  /**
   * Called after {@code request}, from the robot's meta, was applied to its program: on the robot's
   * thread, at its adaptation point, so whatever it records is in step with the cycles. Does
   * nothing by default.
   */
  protected void adapted(Adaptation.ApplyBehavior request) {}

  /** The cycles run so far. */
  public final long cycles() {
    return cycles;
  }

  /** The failures of its modules so far. */
  public final long errors() {
    return errors;
  }

  /** One cycle as the program of its kernel entity: the modules, then the reified cycle. */
  final void kernelCycle(InstantContext now) {
    instant = now;
    cycling = Thread.currentThread();
    try {
      forget();
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
   * Applies the program's side of {@code request}, at the kernel entity's adaptation point: builds
   * the parts it names from the kind's catalog and changes the program.
   *
   * @throws IllegalArgumentException the request does not suit the program (an unknown name,
   *     unsuitable parameters, a cycle): nothing changed, and the meta is told why
   */
  final void applyRequest(Adaptation.ApplyBehavior request) {
    if (request.behavior().equals(RobotKind.CYCLE)) {
      throw new IllegalArgumentException(
          "robot " + name + ": a cycle is its clock's to run, not a request's");
    }
    Map<String, Object> in = RobotKind.input(request);
    ProgramChange.Change change =
        switch (request.behavior()) {
          case RobotKind.SET_SCHEDULING -> setSchedulingOf(in);
          case RobotKind.CHANGE_MODULE ->
              new ProgramChange.ChangeModule((BehaviorModule) build(CatalogEntry.Part.MODULE, in));
          case RobotKind.ADD_SCHEMA ->
              new ProgramChange.AddSchema((Schema) build(CatalogEntry.Part.SCHEMA, in));
          case RobotKind.REMOVE_SCHEMA -> new ProgramChange.RemoveSchema(text(in, RobotKind.NAME));
          case RobotKind.ADD_CONNECTOR ->
              new ProgramChange.AddConnector((Connector) build(CatalogEntry.Part.CONNECTOR, in));
          case RobotKind.REMOVE_CONNECTOR ->
              new ProgramChange.RemoveConnector((Connector) build(CatalogEntry.Part.CONNECTOR, in));
          case RobotKind.SET_PARAMETER -> {
            tune(in);
            yield null;
          }
          default -> throw new IllegalArgumentException("robot " + name + ": " + request);
        };
    if (change != null) {
      applyChange(change);
    }
    adapted(request);
  }

  /**
   * The kind's behaviors changed while the robot runs (flow 5): its catalog is the new one, and a
   * schema the kind forgot is removed from the program at the beginning of the next cycle.
   */
  final void catalogChanged(Behaviors<?> behaviors) {
    Behaviors<?> before = catalog;
    catalog = behaviors;
    for (Behavior<?> b : before.all()) {
      if (b instanceof CatalogEntry<?, ?> e
          && e.part() == CatalogEntry.Part.SCHEMA
          && behaviors.lookup(b.name()).isEmpty()) {
        forgotten.add(e.partName());
      }
    }
  }

  /** Removes the running schemas the kind forgot. On the robot's thread. */
  private void forget() {
    if (forgotten.isEmpty()) {
      return;
    }
    Set<String> running = new HashSet<>();
    program.schemas().forEach(s -> running.add(s.name()));
    for (String schema : forgotten) {
      if (running.contains(schema)) {
        try {
          applyChange(new ProgramChange.RemoveSchema(schema));
        } catch (IllegalArgumentException e) {
          errors++;
          errorHandler.onError(name, "kind forgot schema " + schema, e);
        }
      }
    }
    forgotten.clear();
  }

  private ProgramChange.Change setSchedulingOf(Map<String, Object> in) {
    List<Schema> schemas = new ArrayList<>();
    for (Object schema : list(in, RobotKind.SCHEMAS)) {
      schemas.add(
          (Schema) build(CatalogEntry.Part.SCHEMA, Map.of(RobotKind.NAME, String.valueOf(schema))));
    }
    List<Connector> connectors = new ArrayList<>();
    for (Object connector : list(in, RobotKind.CONNECTORS)) {
      connectors.add(
          (Connector)
              build(
                  CatalogEntry.Part.CONNECTOR, Map.of(RobotKind.NAME, String.valueOf(connector))));
    }
    return new ProgramChange.SetScheduling(schemas, connectors);
  }

  /** Builds the part a request names, from the kind's catalog as this robot last heard it. */
  private Object build(CatalogEntry.Part part, Map<String, Object> in) {
    String partName = text(in, RobotKind.NAME);
    Map<?, ?> parameters =
        in.get(RobotKind.PARAMETERS) instanceof Map<?, ?> p ? p : Map.<String, Object>of();
    Behaviors<?> known = catalog;
    if (!(known.lookup(part.behavior(partName)).orElse(null) instanceof CatalogEntry<?, ?> entry)) {
      List<String> names = new ArrayList<>();
      for (Behavior<?> b : known.all()) {
        if (b instanceof CatalogEntry<?, ?> e && e.part() == part) {
          names.add(e.partName());
        }
      }
      throw new IllegalArgumentException(
          "robot "
              + name
              + ": its kind has no "
              + part.word
              + " '"
              + partName
              + "' in its catalog; it has "
              + names);
    }
    return entry.build(this, Parameters.of(part.word + " " + partName, parameters));
  }

  private void tune(Map<String, Object> in) {
    String module = text(in, RobotKind.MODULE);
    for (BehaviorModule m : program.schedule().modules()) {
      if (m.name().equals(module)) {
        if (!(m instanceof Tunable tunable)) {
          throw new IllegalArgumentException(
              "robot " + name + ": module '" + module + "' has no parameters to set (not Tunable)");
        }
        tunable.tune(
            text(in, RobotKind.PARAMETER),
            requireNonNull(in.get(RobotKind.VALUE), RobotKind.VALUE));
        changes++;
        return;
      }
    }
    throw new IllegalArgumentException(
        "robot " + name + ": no module '" + module + "' in its program to set a parameter of");
  }

  private String text(Map<String, Object> in, String key) {
    if (!(in.get(key) instanceof String s)) {
      throw new IllegalArgumentException(
          "robot " + name + ": the request " + in + " has no " + key + " string");
    }
    return s;
  }

  private List<?> list(Map<String, Object> in, String key) {
    if (!(in.get(key) instanceof List<?> l)) {
      throw new IllegalArgumentException(
          "robot " + name + ": the request " + in + " has no " + key + " list");
    }
    return l;
  }

  /**
   * Applies {@code change} to the program, keeping the compiled cycle of a module change.
   *
   * @throws IllegalArgumentException the program refuses it; nothing changed
   */
  private void applyChange(ProgramChange.Change change) {
    long before = program.version();
    program.apply(change);
    if (change instanceof ProgramChange.ChangeModule c && plan != null && planVersion == before) {
      plan.replace(c.replacement());
      planVersion = program.version();
    }
    changes++;
  }

  /** Every module in schedule order, then the body's end of cycle. */
  private void react() {
    cycles++;
    long now = time.nanoTime();
    plan().run(now, body, failures);
    body.endCycle();
  }

  private Plan plan() {
    Plan current = plan;
    if (current == null || planVersion != program.version()) {
      connectorStates.keySet().retainAll(new HashSet<>(program.connectors()));
      current =
          new Plan(
              program.schedule(),
              program.schemas(),
              program.connectors(),
              c -> connectorStates.computeIfAbsent(c, k -> new ConnectorState()));
      plan = current;
      planVersion = program.version();
    }
    return current;
  }

  private void moduleFailed(BehaviorModule module, Exception error) {
    errors++;
    errorHandler.onError(name, module.name(), error);
  }
}

package org.armgals.examples.sim;

import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.locks.LockSupport;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.ShutdownMode;
import org.armgals.active.TimeSource;
import org.armgals.active.jms.EmbeddedBroker;
import org.armgals.active.jms.JmsTransport;
import org.armgals.active.jms.Presence;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.gals.Island;
import org.armgals.kernel.AdaptationPoint;
import org.armgals.kernel.EntityOptions;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.KernelOptions;
import org.armgals.kernel.NotificationPolicy;
import org.armgals.kernel.ReflectionEvent;
import org.armgals.kernel.StructuralMeta;
import org.armgals.maam.AbstractRobot;
import org.armgals.maam.BMetaRobot;
import org.armgals.maam.RobotKind;
import org.armgals.maam.sim.Simulation;
import org.armgals.representation.p.PState;
import org.jspecify.annotations.Nullable;

/**
 * The reflective side of a run (paper figure 8): the runtime and the ARM kernel its robots are
 * entities of, their islands on the simulation's time, and their meta level, made in the robots'
 * JVM ({@code --meta local}) or in a JVM of its own over the broker ({@code --meta remote}), with
 * the same code ({@link MetaLevel}). On virtual time each robot keeps in lock step with its meta,
 * one cycle behind (a request decided on cycle {@code n} is applied at the adaptation point of
 * cycle {@code n + 1}), so runs are reproducible; paced to real time ({@code --realtime}) the
 * robots never wait for it. It records the loop ({@value #LOOP}) and journals each request applied
 * with the reason its meta gave.
 *
 * <p>Used on the thread that runs the simulation: {@link #open}, then {@link #island} and {@link
 * #start} for each robot, {@link #ready} before the first cycle, {@link #step} in the controllers,
 * {@link #finish} after the last cycle, {@link #close}.
 */
public final class Reflection implements AutoCloseable {
  /** The loop's record, one JSON object per line: what {@code armgals replay} compares too. */
  public static final String LOOP = "loop.jsonl";

  /** The log of a meta level's JVM. */
  static final String META_LOG = "meta.log";

  static final String META_LOOP = ".meta-loop.jsonl";
  static final String META_FIGURES = ".meta-figures.jsonl";
  static final String META_READY = ".meta-ready";

  /** How long a cycle waits for its meta level in lock step before the robots run free. */
  static final Duration LOCK_STEP_TIMEOUT = Duration.ofSeconds(30);

  /** How long a meta level's JVM has to start and take every robot. */
  static final Duration META_START = Duration.ofSeconds(90);

  private final Simulation sim;
  private final RunSettings settings;
  private final String example;
  private final @Nullable MetaLevel level;
  private final Journal journal;
  private final LoopRecorder recorder;
  private final List<Island> islands = new ArrayList<>();
  private final Map<String, Integer> atoms = new LinkedHashMap<>();
  private final Map<String, AbstractRobot> robots = new LinkedHashMap<>();
  private final Map<String, Island> islandOf = new LinkedHashMap<>();
  private final Map<String, BMetaRobot> metaOf = new LinkedHashMap<>();
  private final List<MetaLevel.Watch> watches = new ArrayList<>();
  private Map<String, StructuralMeta<PState>> kinds = Map.of();
  private final ActiveRuntime runtime;
  private final Kernel kernel;
  private @Nullable EmbeddedBroker broker;
  private @Nullable JmsTransport transport;
  private @Nullable Presence presence;
  private @Nullable ChildJvm metaJvm;
  private @Nullable String brokerUrl;
  private @Nullable String prefix;
  private BrokerLogin login = BrokerLogin.NONE;
  private List<Summary.Entry> metaFigures = List.of();
  private boolean finished;

  private Reflection(
      Simulation sim,
      RunSettings settings,
      String example,
      @Nullable MetaLevel level,
      Journal journal) {
    this.sim = sim;
    this.settings = settings;
    this.example = example;
    List<Map<String, Object>> replayed = REPLAYING.get();
    this.level = level != null && replayed != null ? new ReplayedMetaLevel(level, replayed) : level;
    this.journal = journal;
    this.recorder = new LoopRecorder(settings.period().toNanos(), sim::cycle, TimeSource.system());
    boolean remote = this.level != null && settings.meta() == RunSettings.MetaPlace.REMOTE;
    String name = example + "-" + ProcessHandle.current().pid() + "-" + RUNS.incrementAndGet();
    ActiveRuntime.Builder builder =
        ActiveRuntime.builder().name(name).workers(WORKERS.get()).jmx(false);
    if (remote) {
      try {
        JmsTransport t = connect(name);
        transport = t;
        builder.transport(t);
      } catch (RuntimeException | Error e) {
        closeTransport();
        throw e;
      }
    }
    runtime = builder.build();
    kernel =
        org.armgals.kernel.StructuralMeta.bootstrap(
            runtime,
            KernelOptions.defaults()
                .withTimeSource(sim::timeNanos)
                .withJmx(true)
                .withListener(recorder));
    try {
      settle(remote, name);
    } catch (RuntimeException | Error e) {
      close();
      throw e;
    }
  }

  /** The rest of the opening, once the runtime and the kernel exist: presence, kinds, metas. */
  private void settle(boolean remote, String name) {
    recorder.ignore(kernel.basicBehavioralMeta().address());
    if (remote) {
      presence =
          login
              .on(Presence.builder(), requireNonNull(brokerUrl, "brokerUrl"))
              .prefix(requireNonNull(prefix, "prefix"))
              .runtime(name)
              .listener(kernel.presenceListener())
              .failRequestsOf(requireNonNull(transport, "transport"))
              .build();
    }
    MetaLevel meta = this.level;
    kinds = meta == null ? Map.of() : Map.copyOf(meta.kinds(kernel));
    if (meta != null) {
      for (MetaLevel.Watch w : meta.watches(this::note)) {
        watches.add(w);
        for (String robot : w.robots()) {
          metaOf.put(robot, w.meta());
        }
        if (!remote) { // in remote mode these stay unstarted: their twins run in the meta's JVM
          w.meta().start(kernel);
          recorder.watchMeta(w.meta().name());
        }
      }
    }
  }

  /** The loop's record of a free run being replayed on this thread; null when not replaying. */
  private static final ThreadLocal<List<Map<String, Object>>> REPLAYING = new ThreadLocal<>();

  /**
   * Runs {@code run} with every reflective side it opens on this thread replaying {@code loop}, the
   * record of a free run: its meta level asks for the requests the record says were applied, at the
   * cycles it says ({@link ReplayedMetaLevel}).
   */
  static <T> T replaying(List<Map<String, Object>> loop, java.util.function.Supplier<T> run) {
    requireNonNull(loop, "loop");
    REPLAYING.set(List.copyOf(loop));
    try {
      return run.get();
    } finally {
      REPLAYING.remove();
    }
  }

  /**
   * Whether this thread replays a free run ({@link #replaying(List, java.util.function.Supplier)}).
   */
  static boolean replaying() {
    return REPLAYING.get() != null;
  }

  private static final java.util.concurrent.atomic.AtomicInteger RUNS =
      new java.util.concurrent.atomic.AtomicInteger();

  /** The workers of the robots' runtime: 2 (the tests vary it to show they change nothing). */
  static final java.util.concurrent.atomic.AtomicInteger WORKERS =
      new java.util.concurrent.atomic.AtomicInteger(2);

  /**
   * Opens the reflective side of a run of {@code example} with {@code settings}: in remote mode,
   * the broker (embedded over netty on 127.0.0.1, unless {@code --broker} names one) and a
   * transport; the kernel, on the simulation's time; the kinds of the meta level; in local mode its
   * meta-entities.
   *
   * @param level the example's meta level; null for robots without one (they notify no one)
   */
  public static Reflection open(
      Simulation sim,
      RunSettings settings,
      String example,
      @Nullable MetaLevel level,
      Journal journal) {
    requireNonNull(sim, "sim");
    requireNonNull(settings, "settings");
    requireNonNull(example, "example");
    requireNonNull(journal, "journal");
    return new Reflection(sim, settings, example, level, journal);
  }

  /**
   * The transport of the robots' runtime: to {@code --broker} (with the login of {@value
   * BrokerLogin#USER} and {@value BrokerLogin#PASSWORD} in the environment, if any), or to an
   * embedded broker over netty on a free port of 127.0.0.1, which requires the login it generates
   * for this run; the meta level's JVM gets the login in its environment.
   */
  private JmsTransport connect(String name) {
    if (settings.broker().isPresent()) {
      brokerUrl = settings.broker().get().toString();
      login = BrokerLogin.fromEnvironment();
    } else {
      EmbeddedBroker b = EmbeddedBroker.start(freePort());
      broker = b;
      brokerUrl = b.nettyUrl().orElseThrow();
      login = BrokerLogin.of(b);
    }
    prefix = "armgals-" + name;
    return Kernel.allowKernelEvents(login.on(JmsTransport.builder().prefix(prefix), brokerUrl))
        .build();
  }

  /** The kernel the robots are entities of. */
  public Kernel kernel() {
    return kernel;
  }

  /** The runtime of the robots' entities. */
  public ActiveRuntime runtime() {
    return runtime;
  }

  /**
   * The kind of the robot {@code robot}, as the meta level defined it.
   *
   * @throws IllegalArgumentException the meta level defines none for it
   */
  public StructuralMeta<PState> kind(String robot) {
    StructuralMeta<PState> kind = kinds.get(robot);
    if (kind == null) {
      throw new IllegalArgumentException(
          "no kind for robot '" + robot + "'; the meta level defines kinds for " + kinds.keySet());
    }
    return kind;
  }

  /**
   * A new island named {@code name}, released by the simulation's controllers ({@link #step}) on
   * its time, one release per control period, adapting at {@code point}.
   */
  public Island island(String name, AdaptationPoint point) {
    Island island =
        Island.builder(name, runtime)
            .period(settings.period())
            .adaptationPoint(point)
            .timeSource(sim::timeNanos)
            .jmx(false)
            .build();
    islands.add(island);
    return island;
  }

  /**
   * Starts {@code robot}, the robot of atom {@code atom}, as a kernel entity on {@code island}
   * notifying its meta as {@code policy} says: in lock step with it on virtual time, free paced to
   * real time. A robot the meta level watches not is started with the kernel's basic meta and a
   * kind of its own.
   */
  public void start(AbstractRobot robot, int atom, Island island, NotificationPolicy policy) {
    requireNonNull(robot, "robot");
    requireNonNull(island, "island");
    requireNonNull(policy, "policy");
    String name = robot.name();
    atoms.put(name, atom);
    robots.put(name, robot);
    islandOf.put(name, island);
    recorder.watch(name);
    EntityOptions options = island.entityOptions().withNotification(policy);
    BMetaRobot watcher = metaOf.get(name);
    if (watcher != null && !settings.realTime()) {
      options = options.withLockStep(1, LOCK_STEP_TIMEOUT);
    }
    StructuralMeta<PState> kind =
        kinds.containsKey(name)
            ? kinds.get(name)
            : RobotKind.define(kernel, name + "-kind", robot.observation());
    if (watcher != null && isRemote()) {
      robot.start(island, kind, options); // its meta, in another JVM, takes it in ready()
    } else {
      robot.start(island, kind, watcher != null ? watcher : kernel.basicBehavioralMeta(), options);
    }
  }

  private boolean isRemote() {
    return transport != null;
  }

  /**
   * Before the first cycle: sets each meta's first filter; in remote mode, starts the meta level's
   * JVM and waits until it has taken every robot.
   *
   * @throws IllegalStateException the meta level's JVM did not start or take the robots in time
   */
  public void ready() {
    if (level == null) {
      return;
    }
    if (!isRemote()) {
      for (MetaLevel.Watch w : watches) {
        for (String robot : w.robots()) {
          w.meta().setFilter(robots.get(robot), w.filter()).touch();
        }
      }
      return;
    }
    JmsTransport t = requireNonNull(transport, "transport");
    robots.forEach((name, robot) -> t.register(name, robot.address()));
    Map<String, Integer> before = new LinkedHashMap<>();
    metaOf.keySet().forEach(name -> before.put(name, robots.get(name).queueDepth()));
    Path out = settings.out();
    ChildJvm child =
        ChildJvm.start(
            "the meta level's JVM",
            MetaMain.class,
            MetaMain.args(example, requireNonNull(brokerUrl), requireNonNull(prefix), settings),
            login.environment(),
            out.resolve(META_LOG),
            "192m",
            ChildJvm.Priority.LOWER); // the robots keep their period when the cores are scarce
    metaJvm = child;
    awaitFile(child, out.resolve(META_READY));
    for (String watched : metaOf.keySet()) {
      AbstractRobot robot = requireNonNull(robots.get(watched), watched);
      long deadline = System.nanoTime() + META_START.toNanos();
      while (robot.queueDepth() <= before.get(watched)) { // its meta's attachment is on its way
        if (child.ended() || System.nanoTime() > deadline) {
          throw new IllegalStateException(
              child
                  + " took robot "
                  + robot.name()
                  + " but it never heard; its last lines:\n"
                  + child.tail());
        }
        LockSupport.parkNanos(1_000_000L);
      }
    }
  }

  private static void awaitFile(ChildJvm child, Path file) {
    long deadline = System.nanoTime() + META_START.toNanos();
    while (!Files.exists(file)) {
      if (child.ended()) {
        throw new IllegalStateException(
            child + " ended before it took the robots; its last lines:\n" + child.tail());
      }
      if (System.nanoTime() > deadline) {
        throw new IllegalStateException(
            child
                + " did not take the robots within "
                + META_START
                + "; its last lines:\n"
                + child.tail());
      }
      LockSupport.parkNanos(5_000_000L);
    }
  }

  /**
   * One cycle of {@code island}, from a controller of the simulation: its release, then the
   * journal's entries for the requests applied in it.
   */
  public void step(Island island) {
    island.step();
    // The requests one robot applied in this cycle for one reason are one adaptation of it.
    Map<String, List<String>> whats = new LinkedHashMap<>();
    for (ReflectionEvent.Applied a : recorder.drainApplied()) {
      Integer atom = atoms.get(a.entity());
      if (atom == null) {
        continue;
      }
      String what = RobotKind.describe(a.request().adaptation());
      if (!a.applied()) {
        journal.note(atom, "refused " + what + ": " + a.refusal());
        continue;
      }
      String why = RobotKind.reason(a.request().adaptation()).orElse("asked by the meta level");
      whats.computeIfAbsent(a.entity() + "\n" + why, k -> new ArrayList<>()).add(what);
    }
    whats.forEach(
        (key, what) -> {
          String robot = key.substring(0, key.indexOf('\n'));
          String why = key.substring(key.indexOf('\n') + 1);
          journal.adaptation(atoms.get(robot), String.join("; ", what), why);
        });
  }

  /**
   * Tells {@code watcher} each record of the loop from now on as it is made, as {@value #LOOP} will
   * have it, on the thread that makes it: the records of the meta's side too when the meta runs in
   * the robots' JVM; in another, only the robots' side (the meta's comes at {@link #finish}).
   */
  public void watch(RunWatcher watcher) {
    requireNonNull(watcher, "watcher");
    recorder.tap(line -> watcher.loop(LoopJson.write(LoopRecorder.merge(List.of(line)).get(0))));
  }

  /**
   * Each robot's program now, by name: its schemas ({@code schemas}) and its modules in the order
   * they run ({@code schedule}). On the thread that runs the simulation, between cycles.
   */
  public Map<String, Object> programs() {
    Map<String, Object> programs = new LinkedHashMap<>();
    robots.forEach(
        (name, robot) -> {
          Map<String, Object> program = new LinkedHashMap<>();
          program.put(
              "schemas",
              robot.metaRobot().schemas().stream().map(org.armgals.maam.Schema::name).toList());
          program.put("schedule", robot.schedule().names());
          programs.put(name, program);
        });
    return programs;
  }

  /**
   * Asks each meta in the robots' JVM for its model of each robot it watches and tells {@code sink}
   * the robot and the model when it answers, on the meta's thread; asks nothing of a meta in
   * another JVM.
   */
  public void models(java.util.function.BiConsumer<String, Map<String, Object>> sink) {
    requireNonNull(sink, "sink");
    if (level == null || isRemote() || finished) {
      return;
    }
    for (MetaLevel.Watch w : watches) {
      for (String robot : w.robots()) {
        AbstractRobot base = robots.get(robot);
        if (base == null) {
          continue;
        }
        w.meta()
            .model(base)
            .toCompletionStage()
            .thenAccept(view -> sink.accept(robot, model(view)));
      }
    }
  }

  private static Map<String, Object> model(org.armgals.kernel.ModelView view) {
    Map<String, Object> m = new LinkedHashMap<>();
    m.put("state", String.valueOf(view.state()));
    m.put("last notification", view.lastSeq());
    m.put("filter", view.filter());
    m.put("requested version", view.requestedVersion());
    m.put("applied version", view.appliedVersion());
    m.put("held back", view.suppressedAdaptations());
    m.put("refused", view.refusedAdaptations());
    if (view.lastRefusal() != null) {
      m.put("last refusal", view.lastRefusal());
    }
    m.put("lock step", view.lockStep());
    m.put("lost", view.lost());
    return m;
  }

  /** A meta's note, recorded on the loop's time line. */
  private void note(String robot, long nanoTime, String text) {
    String meta = metaOf.containsKey(robot) ? metaOf.get(robot).name() : "meta";
    recorder.note(meta, robot, nanoTime, text);
  }

  /**
   * After the last cycle: waits until the metas have handled everything sent to them (local), or
   * stops the meta level's JVM and reads what it recorded (remote); writes the loop's record into
   * {@code dir} and answers the summary's figures of the loop and of the meta level.
   */
  public List<Summary.Entry> finish(Path dir) {
    requireNonNull(dir, "dir");
    if (finished) {
      throw new IllegalStateException("the reflective side of this run is finished already");
    }
    finished = true;
    List<LoopRecorder.Line> lines = new ArrayList<>(recorder.lines());
    List<Summary.Entry> figures = new ArrayList<>();
    if (level != null && !isRemote()) {
      for (MetaLevel.Watch w : watches) {
        for (String robot : w.robots()) {
          w.meta().model(robots.get(robot)).getValue(); // the meta has handled all sent to it
        }
      }
      lines = new ArrayList<>(recorder.lines());
      metaFigures = level.figures();
    } else if (isRemote()) {
      ChildJvm child = requireNonNull(metaJvm, "metaJvm");
      if (!child.ended()) {
        metaOf.keySet().forEach(robot -> child.say(robot + " " + islandOf.get(robot).instant()));
      }
      child.close(MetaMain.SETTLE.plusSeconds(10));
      lines.addAll(MetaMain.readLoop(settings.out().resolve(META_LOOP)));
      metaFigures = MetaMain.readFigures(settings.out().resolve(META_FIGURES));
      deleteQuietly(settings.out().resolve(META_LOOP));
      deleteQuietly(settings.out().resolve(META_FIGURES));
      deleteQuietly(settings.out().resolve(META_READY));
    }
    List<Map<String, Object>> loop = LoopRecorder.merge(lines);
    write(dir.resolve(LOOP), loop);
    figures.addAll(
        LoopSummary.of(
                loop,
                level != null,
                settings,
                isRemote(),
                recorder.overruns(),
                recorder.latencies(loop))
            .entries());
    figures.addAll(metaFigures);
    return figures;
  }

  static void write(Path file, List<Map<String, Object>> loop) {
    try (Writer out = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
      for (Map<String, Object> record : loop) {
        out.write(LoopJson.write(record));
        out.write('\n');
      }
    } catch (IOException e) {
      throw new UncheckedIOException("cannot write the loop's record " + file, e);
    }
  }

  private static void deleteQuietly(Path file) {
    try {
      Files.deleteIfExists(file);
    } catch (IOException e) {
      throw new UncheckedIOException("cannot delete " + file, e);
    }
  }

  /** Kills the meta level's JVM at once, as a crash would: for the tests of autonomy. */
  void killMeta() {
    ChildJvm child = metaJvm;
    if (child != null) {
      child.kill();
    }
  }

  @Override
  public void close() {
    islands.forEach(Island::close);
    ChildJvm child = metaJvm;
    if (child != null) {
      child.close();
    }
    kernel.close();
    runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5));
    if (presence != null) {
      presence.close();
    }
    closeTransport();
  }

  private void closeTransport() {
    if (transport != null) {
      transport.close();
    }
    if (broker != null) {
      broker.close();
    }
  }

  private static int freePort() {
    try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      return socket.getLocalPort();
    } catch (IOException e) {
      throw new UncheckedIOException("cannot find a free port on 127.0.0.1 for the broker", e);
    }
  }
}

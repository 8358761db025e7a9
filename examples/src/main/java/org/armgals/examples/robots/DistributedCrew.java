package org.armgals.examples.robots;

import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.NavigableMap;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Collectors;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.ShutdownMode;
import org.armgals.active.TimeSource;
import org.armgals.active.jms.EmbeddedBroker;
import org.armgals.active.jms.JmsTransport;
import org.armgals.examples.run.RunSettings;
import org.armgals.examples.run.Summary;
import org.armgals.examples.sim.BrokerLogin;
import org.armgals.examples.sim.Crew;
import org.armgals.examples.sim.Journal;
import org.armgals.examples.sim.LoopRecord;
import org.armgals.examples.sim.Reflection;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.Stimulus;
import org.armgals.maam.sim.Simulation;
import org.armgals.maam.spi.Atom;
import org.armgals.maam.spi.Body;
import org.armgals.maam.spi.Leg;
import org.armgals.maam.spi.LegAngles;
import org.armgals.maam.spi.Tilt;
import org.jspecify.annotations.Nullable;

/**
 * A run of {@link Distributed}: the broker (embedded, unless given), the world's runtime, mailbox
 * and meta level ({@link DistributedMetaLevel}), an atom JVM per atom, and a controller per atom
 * that trades readings for commands with it. Built and used on the thread that runs the simulation.
 *
 * <p>Each cycle, the first controller to run sends every atom its readings; then each atom's
 * controller waits for the commands that answer them, at most its patience (lock step: generous;
 * paced to real time: one period), and applies the latest commands it has. A cycle whose answer did
 * not come in time is a missed cycle of that atom. In lock step the first controller also waits,
 * before it sends the readings, for the meta level to keep up with each atom ({@link
 * DistributedMetaLevel#keepUp}), and journals the requests that apply from this cycle on.
 */
final class DistributedCrew implements Crew {
  /** How long the atoms' JVMs have to start and join. */
  static final Duration JOIN = Duration.ofSeconds(90);

  /**
   * How long the world waits for an atom's answer in lock step: long enough for the first round
   * trip (class loading in three JVMs) and for the stalls of a loaded machine, seen over 2 s.
   */
  static final Duration LOCKSTEP_WAIT = Duration.ofSeconds(10);

  /** How long the probe of an external broker waits for its host to answer. */
  private static final int PROBE_TIMEOUT_MILLIS = 3000;

  private static final AtomicInteger RUNS = new AtomicInteger();

  private final TimeSource time = TimeSource.system();
  private final Simulation sim;
  private final Duration patience;
  private final boolean lockStep;
  private final Journal journal;
  private final RunSettings settings;
  private final LoopRecord loop;
  private final List<Path> loopFiles = new ArrayList<>();
  private boolean finished;
  private final List<DistributedAtomProcess> processes = new ArrayList<>();
  private final List<DistributedWire.Joined> joined = new ArrayList<>();
  private final Map<Integer, Long> missedOf = new TreeMap<>();
  private final Map<Integer, NavigableMap<Long, Double>> strokes = new TreeMap<>();
  private final Set<Integer> gone = new HashSet<>();
  private @Nullable EmbeddedBroker broker;
  private @Nullable JmsTransport transport;
  private @Nullable ActiveRuntime runtime;
  private @Nullable DistributedWorld world;
  private @Nullable ActiveObject<DistributedWorld> mailbox;
  private @Nullable DistributedMetaLevel metaLevel;
  private long published = -1;
  private long missed;
  private long awaited;

  private DistributedCrew(
      Simulation sim, Duration patience, RunSettings settings, Journal journal) {
    this.sim = sim;
    this.patience = patience;
    this.settings = settings;
    this.lockStep = !settings.realTime();
    this.journal = journal;
    this.loop = new LoopRecord(settings.period().toNanos(), sim::cycle);
  }

  /**
   * Starts the broker (unless {@code url} names one), the world's runtime and the atoms' JVMs,
   * waits until every atom has joined, and installs the controllers.
   *
   * @param url an external broker, or null for an embedded one
   * @param settings the run's: the directory of the atoms' logs ({@code out}), the period, lock
   *     step or real time
   * @throws IllegalArgumentException the external broker cannot be reached, saying what to do
   * @throws IllegalStateException an atom's JVM did not start or join, naming it; nothing is left
   *     running
   */
  static DistributedCrew start(
      Simulation sim,
      @Nullable String url,
      BrokerLogin login,
      RunSettings settings,
      Journal journal) {
    requireNonNull(sim, "sim");
    requireNonNull(settings, "settings");
    requireNonNull(journal, "journal");
    Duration period = settings.period();
    DistributedCrew crew =
        new DistributedCrew(sim, settings.realTime() ? period : LOCKSTEP_WAIT, settings, journal);
    try {
      crew.open(url, login, settings.out(), period);
      return crew;
    } catch (RuntimeException | Error e) {
      crew.close();
      throw e;
    }
  }

  private void open(@Nullable String url, BrokerLogin given, Path logs, Duration period) {
    String brokerUrl;
    BrokerLogin login = given;
    if (url == null) {
      // The embedded broker requires the login it generates for this run; the atoms' JVMs get it
      // in their environment.
      EmbeddedBroker b = EmbeddedBroker.start(freePort());
      broker = b;
      brokerUrl = b.nettyUrl().orElseThrow();
      login = BrokerLogin.of(b);
    } else {
      brokerUrl = url;
    }
    long pid = ProcessHandle.current().pid();
    String prefix = "armgals-distributed-" + pid;
    JmsTransport.Builder builder =
        Kernel.allowKernelEvents(
            JmsTransport.builder().prefix(prefix).allow(DistributedWire.ALLOWED));
    try {
      if (url != null) {
        probe(url);
      }
      transport = login.on(builder, brokerUrl).build();
    } catch (RuntimeException e) {
      if (url == null) {
        throw e;
      }
      throw new IllegalArgumentException(
          "could not reach the broker at "
              + url
              + " ("
              + rootMessage(e)
              + "): start it, check the URL (and "
              + BrokerLogin.USER
              + "/"
              + BrokerLogin.PASSWORD
              + " if it needs a login), or leave --broker out to run on an embedded broker",
          e);
    }
    ActiveRuntime r =
        ActiveRuntime.builder()
            .name("world-" + pid + "-" + RUNS.incrementAndGet())
            .workers(1)
            .jmx(false)
            .transport(transport)
            .build();
    runtime = r;
    DistributedWorld w = new DistributedWorld(time);
    world = w;
    ActiveObject<DistributedWorld> m = r.spawn(w);
    mailbox = m;
    DistributedMetaLevel level = DistributedMetaLevel.open(r, period.toNanos(), time, loop);
    metaLevel = level;
    double capacity = sim.scene().params().batteryCapacity();
    List<Integer> ids = sim.atomIds();
    for (int i = 0; i < ids.size(); i++) {
      int atom = ids.get(i);
      Path loopFile = logs.resolve(".atom-" + atom + "-loop.jsonl");
      loopFiles.add(loopFile);
      DistributedAtomProcess p =
          DistributedAtomProcess.start(
              atom,
              DistributedAtomMain.args(
                  atom, i, ids.size(), brokerUrl, prefix, m.address(), period, capacity, loopFile),
              logs.resolve("atom-" + atom + ".log"),
              login);
      processes.add(p);
      p.handle().onExit().thenRun(() -> w.ended(atom));
    }
    for (DistributedAtomProcess p : processes) {
      DistributedWire.Joined j = awaitJoined(w, p);
      joined.add(j);
      try {
        level.take(
            j.atom(), requireNonNull(transport, "transport"), JOIN, () -> w.hasEnded(j.atom()));
      } catch (RuntimeException e) {
        throw new IllegalStateException(
            p + ": " + e.getMessage() + "; its last lines:\n" + p.tail(), e);
      }
      // No pid here: a run in lock step leaves the same trace every time.
      journal.note(
          j.atom(),
          "its robot joined from a JVM of its own; the meta level in the world's JVM takes it");
    }
    for (int atom : ids) {
      sim.setController(atom, (body, cycle) -> control(atom, body, cycle));
    }
  }

  private static DistributedWire.Joined awaitJoined(DistributedWorld w, DistributedAtomProcess p) {
    DistributedWire.Joined j;
    try {
      j = w.awaitJoined(p.atom(), JOIN);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new IllegalStateException("interrupted while waiting for " + p, e);
    }
    if (j == null) {
      throw new IllegalStateException(
          p
              + (w.hasEnded(p.atom()) ? " ended" : " did not join within " + JOIN)
              + " before joining the world; its last lines:\n"
              + p.tail());
    }
    return j;
  }

  /**
   * Atom {@code atom}'s cycle: the commands its robot sent from its own JVM go to {@code body}, the
   * body the simulation hands the atom's controller.
   */
  private void control(int atom, Body body, long cycle) {
    DistributedWorld w = requireNonNull(world, "world");
    if (cycle != published) {
      keepUp(w);
      publish(cycle);
      published = cycle;
    }
    DistributedWire.Commands commands;
    try {
      commands = w.awaitCommands(atom, cycle, patience);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new IllegalStateException("interrupted while waiting for atom " + atom, e);
    }
    awaited++;
    if (commands == null || commands.cycle() < cycle) {
      missed++;
      missedOf.merge(atom, 1L, Long::sum);
    }
    if (commands != null) {
      apply(body, commands);
      strokes
          .computeIfAbsent(atom, a -> new TreeMap<>())
          .put(commands.timeNanos(), stroke(commands));
    }
    if (w.hasEnded(atom) && gone.add(atom)) {
      journal.note(atom, "its JVM ended: the world goes on without its robot");
    }
  }

  /**
   * Before the readings of a cycle: in lock step, waits until the meta level has handled every
   * notification of the readings before and each atom has acknowledged its requests; then journals
   * the requests that apply from now on. Atoms whose process ended are not waited for.
   */
  private void keepUp(DistributedWorld w) {
    DistributedMetaLevel level = requireNonNull(metaLevel, "metaLevel");
    if (lockStep) {
      for (DistributedWire.Joined j : joined) {
        int atom = j.atom();
        DistributedWire.Commands last = w.latest(atom);
        long deadline = time.nanoTime() + patience.toNanos();
        level.keepUp(atom, last == null ? 0 : last.notified(), deadline, () -> w.hasEnded(atom));
      }
    }
    level.journal(sim.timeNanos(), journal);
  }

  /** How far from their cones' axes the commands drive the legs, at most, rad. */
  private static double stroke(DistributedWire.Commands commands) {
    double most = 0;
    for (double elevation : commands.elevations()) {
      if (!Double.isNaN(elevation)) {
        most = Math.max(most, elevation);
      }
    }
    return most;
  }

  private void publish(long cycle) {
    ActiveRuntime r = requireNonNull(runtime, "runtime");
    Address from = requireNonNull(mailbox, "mailbox").address();
    for (DistributedWire.Joined j : joined) {
      r.ref(j.robot()).send(new Stimulus(from, j.robot(), "readings", readings(j.atom(), cycle)));
    }
  }

  private DistributedWire.Readings readings(int atom, long cycle) {
    Body body = sim.body(atom);
    List<Double> elevations = new ArrayList<>(6);
    List<Double> azimuths = new ArrayList<>(6);
    List<Boolean> contacts = new ArrayList<>(6);
    for (Leg leg : Leg.values()) {
      LegAngles angles = body.read(Atom.angles(leg));
      elevations.add(angles.elevation());
      azimuths.add(angles.azimuth());
      contacts.add(body.read(Atom.contact(leg)));
    }
    Tilt tilt = body.read(Atom.TILT);
    return new DistributedWire.Readings(
        atom,
        cycle,
        sim.timeNanos(),
        elevations,
        azimuths,
        contacts,
        tilt.roll(),
        tilt.pitch(),
        body.read(Atom.BATTERY));
  }

  private static void apply(Body body, DistributedWire.Commands commands) {
    for (Leg leg : Leg.values()) {
      double elevation = commands.elevations().get(leg.ordinal());
      double azimuth = commands.azimuths().get(leg.ordinal());
      if (!Double.isNaN(elevation) && !Double.isNaN(azimuth)) {
        body.command(Atom.target(leg), new LegAngles(elevation, azimuth));
      }
    }
  }

  /** The atoms that joined, in the chain's order. */
  List<DistributedWire.Joined> joined() {
    return List.copyOf(joined);
  }

  /** The atoms' processes, in the chain's order. */
  List<ProcessHandle> processes() {
    return processes.stream().map(DistributedAtomProcess::handle).toList();
  }

  /** The meta level, in the world's JVM. */
  DistributedMetaLevel metaLevel() {
    return requireNonNull(metaLevel, "metaLevel");
  }

  /** The cycles whose answer from atom {@code atom} came too late or not at all. */
  long missedCycles(int atom) {
    return missedOf.getOrDefault(atom, 0L);
  }

  /**
   * The strokes atom {@code atom}'s commands drove its legs to, as the world received them: by the
   * world time of the readings they answered, how far from their cones' axes they went, rad.
   */
  NavigableMap<Long, Double> strokes(int atom) {
    return java.util.Collections.unmodifiableNavigableMap(
        strokes.getOrDefault(atom, new TreeMap<>()));
  }

  /**
   * After the last cycle: in lock step waits until the meta has handled the notifications of the
   * last readings, then lets the atoms leave (each writes its robot's side of the loop's record as
   * it does) and merges every side into {@code dir}'s {@value Reflection#LOOP}.
   *
   * @throws IllegalStateException it finished already
   */
  @Override
  public List<Summary.Entry> finish(Path dir) {
    requireNonNull(dir, "dir");
    if (finished) {
      throw new IllegalStateException("the loop of this run is finished already");
    }
    finished = true;
    keepUp(requireNonNull(world, "world"));
    processes.forEach(DistributedAtomProcess::leave);
    processes.forEach(DistributedAtomProcess::close);
    return LoopRecord.finish(
        dir,
        loop,
        loopFiles,
        settings,
        "in the world's JVM, apart from every atom's, over the broker");
  }

  @Override
  public long missedCycles() {
    return missed;
  }

  @Override
  public List<Summary.Entry> figures() {
    List<Summary.Entry> figures = new ArrayList<>();
    figures.add(
        new Summary.Entry(
            "atom processes",
            joined.stream().map(j -> Long.toString(j.pid())).collect(Collectors.joining(", "))));
    figures.add(new Summary.Entry("late answers", missed + " of " + awaited + " (atoms × cycles)"));
    figures.add(
        new Summary.Entry(
            "world waits",
            String.format(
                Locale.ROOT, "up to %d ms per cycle for each atom", patience.toMillis())));
    DistributedMetaLevel level = metaLevel;
    if (level == null) {
      return figures;
    }
    figures.addAll(level.figures(lockStep, patience));
    for (DistributedWire.Joined j : joined) {
      figures.add(
          new Summary.Entry(
              DistributedCrawler.robotName(j.atom()) + "'s stroke", strokeFigure(level, j.atom())));
    }
    return figures;
  }

  /** What the world saw of an atom's stroke, and the request that changed it. */
  private String strokeFigure(DistributedMetaLevel level, int atom) {
    NavigableMap<Long, Double> seen = strokes(atom);
    Optional<DistributedMeta.Decision> decision = level.decision(atom);
    if (decision.isEmpty()) {
      return String.format(
          Locale.ROOT, "%.2f rad throughout (its battery stayed above half)", most(seen.values()));
    }
    DistributedMeta.Decision d = decision.get();
    return String.format(
        Locale.ROOT,
        "%.2f rad, then %.2f rad from %.2f s (asked for on its battery at %.1f%% at %.2f s)",
        most(seen.headMap(d.fromNanos(), false).values()),
        most(seen.tailMap(d.fromNanos(), true).values()),
        d.fromNanos() / 1e9,
        100 * d.fraction(),
        d.thresholdNanos() / 1e9);
  }

  private static double most(java.util.Collection<Double> strokes) {
    return strokes.stream().mapToDouble(Double::doubleValue).max().orElse(Double.NaN);
  }

  /** Stops the atoms' JVMs (and waits for them), the world's runtime, the transport, the broker. */
  @Override
  public void close() {
    for (DistributedAtomProcess p : processes) {
      p.leave();
    }
    for (DistributedAtomProcess p : processes) {
      p.close();
    }
    // A run not finished (interrupted, or a test's) leaves no side of the loop behind.
    for (Path file : loopFiles) {
      try {
        java.nio.file.Files.deleteIfExists(file);
      } catch (IOException e) {
        throw new UncheckedIOException("cannot delete " + file, e);
      }
    }
    DistributedMetaLevel level = metaLevel;
    if (level != null) {
      level.close();
    }
    ActiveRuntime r = runtime;
    if (r != null) {
      r.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5));
    }
    JmsTransport t = transport;
    if (t != null) {
      t.close();
    }
    EmbeddedBroker b = broker;
    if (b != null) {
      b.close();
    }
  }

  /**
   * Fails fast when nothing answers at a {@code tcp://} broker's address: Artemis would wait for
   * the cluster topology for its call time-out (30 s) before giving up on a host that does not
   * answer.
   */
  private static void probe(String url) {
    URI uri = URI.create(url);
    if (!"tcp".equals(uri.getScheme()) || uri.getHost() == null || uri.getPort() < 0) {
      return;
    }
    try (Socket socket = new Socket()) {
      socket.connect(new InetSocketAddress(uri.getHost(), uri.getPort()), PROBE_TIMEOUT_MILLIS);
    } catch (IOException e) {
      throw new IllegalStateException(e.getMessage() == null ? e.toString() : e.getMessage(), e);
    }
  }

  private static int freePort() {
    try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      return socket.getLocalPort();
    } catch (IOException e) {
      throw new UncheckedIOException("cannot find a free port on 127.0.0.1 for the broker", e);
    }
  }

  private static String rootMessage(Throwable e) {
    Throwable root = e;
    while (root.getCause() != null && root.getCause() != root) {
      root = root.getCause();
    }
    return root.getMessage() == null ? root.toString() : root.getMessage();
  }
}

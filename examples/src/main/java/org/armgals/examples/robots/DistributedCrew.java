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
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.ShutdownMode;
import org.armgals.active.TimeSource;
import org.armgals.active.jms.EmbeddedBroker;
import org.armgals.active.jms.JmsTransport;
import org.armgals.examples.cli.Summary;
import org.armgals.examples.sim.Crew;
import org.armgals.examples.sim.Journal;
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
 * A run of {@link Distributed}: the broker (embedded, unless given), the world's runtime and
 * mailbox, an atom JVM per atom, and a controller per atom that trades readings for commands with
 * it. Built and used on the thread that runs the simulation.
 *
 * <p>Each cycle, the first controller to run sends every atom its readings; then each atom's
 * controller waits for the commands that answer them, at most its patience (lock step: generous;
 * paced to real time: one period), and applies the latest commands it has. A cycle whose answer did
 * not come in time is a missed cycle of that atom.
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

  private final Simulation sim;
  private final Duration patience;
  private final List<DistributedAtomProcess> processes = new ArrayList<>();
  private final List<DistributedWire.Joined> joined = new ArrayList<>();
  private @Nullable EmbeddedBroker broker;
  private @Nullable JmsTransport transport;
  private @Nullable ActiveRuntime runtime;
  private @Nullable DistributedWorld world;
  private @Nullable ActiveObject<DistributedWorld> mailbox;
  private long published = -1;
  private long missed;
  private long awaited;

  private DistributedCrew(Simulation sim, Duration patience) {
    this.sim = sim;
    this.patience = patience;
  }

  /**
   * Starts the broker (unless {@code url} names one), the world's runtime and the atoms' JVMs,
   * waits until every atom has joined, and installs the controllers.
   *
   * @param url an external broker, or null for an embedded one
   * @param logs the directory of the atoms' logs
   * @throws IllegalArgumentException the external broker cannot be reached, saying what to do
   * @throws IllegalStateException an atom's JVM did not start or join, naming it; nothing is left
   *     running
   */
  static DistributedCrew start(
      Simulation sim,
      @Nullable String url,
      String user,
      String password,
      Path logs,
      Duration period,
      boolean realTime,
      Journal journal) {
    requireNonNull(sim, "sim");
    DistributedCrew crew = new DistributedCrew(sim, realTime ? period : LOCKSTEP_WAIT);
    try {
      crew.open(url, user, password, logs, period, journal);
      return crew;
    } catch (RuntimeException | Error e) {
      crew.close();
      throw e;
    }
  }

  private void open(
      @Nullable String url,
      String givenUser,
      String givenPassword,
      Path logs,
      Duration period,
      Journal journal) {
    String brokerUrl;
    String user = givenUser;
    String password = givenPassword;
    if (url == null) {
      // The embedded broker requires the login it generates for this run; the atoms' JVMs get it
      // in their environment.
      EmbeddedBroker b = EmbeddedBroker.start(freePort());
      broker = b;
      brokerUrl = b.nettyUrl().orElseThrow();
      user = b.user();
      password = b.password();
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
      if (user.isEmpty()) {
        builder.broker(brokerUrl);
      } else {
        builder.broker(brokerUrl, user, password);
      }
      transport = builder.build();
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
              + DistributedAtomMain.USER
              + "/"
              + DistributedAtomMain.PASSWORD
              + " if it needs a login), or leave --broker out to run on an embedded broker",
          e);
    }
    ActiveRuntime r =
        ActiveRuntime.builder()
            .name("world-" + pid)
            .workers(1)
            .jmx(false)
            .transport(transport)
            .build();
    runtime = r;
    DistributedWorld w = new DistributedWorld(TimeSource.system());
    world = w;
    ActiveObject<DistributedWorld> m = r.spawn(w);
    mailbox = m;
    List<Integer> ids = sim.atomIds();
    for (int i = 0; i < ids.size(); i++) {
      int atom = ids.get(i);
      DistributedAtomProcess p =
          DistributedAtomProcess.start(
              atom,
              DistributedAtomMain.args(atom, i, ids.size(), brokerUrl, prefix, m.address(), period),
              logs.resolve("atom-" + atom + ".log"),
              user,
              password);
      processes.add(p);
      p.handle().onExit().thenRun(() -> w.ended(atom));
    }
    for (DistributedAtomProcess p : processes) {
      DistributedWire.Joined j = awaitJoined(w, p);
      joined.add(j);
      // No pid here: a run in lock step leaves the same trace every time.
      journal.note(j.atom(), "its robot joined from a JVM of its own");
    }
    for (int atom : ids) {
      sim.setController(atom, (body, cycle) -> control(atom, cycle));
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

  private void control(int atom, long cycle) {
    DistributedWorld w = requireNonNull(world, "world");
    if (cycle != published) {
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
    }
    if (commands != null) {
      apply(sim.body(atom), commands);
    }
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

  @Override
  public long missedCycles() {
    return missed;
  }

  @Override
  public List<Summary.Entry> figures() {
    return List.of(
        new Summary.Entry(
            "atom processes",
            joined.stream().map(j -> Long.toString(j.pid())).collect(Collectors.joining(", "))),
        new Summary.Entry("late answers", missed + " of " + awaited + " (atoms × cycles)"),
        new Summary.Entry(
            "world waits",
            String.format(
                Locale.ROOT, "up to %d ms per cycle for each atom", patience.toMillis())));
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

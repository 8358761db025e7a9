package org.armgals.examples.robots;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.ShutdownMode;
import org.armgals.active.jms.JmsTransport;
import org.armgals.examples.sim.BrokerLogin;
import org.armgals.examples.sim.LoopRecord;
import org.armgals.gals.Emission;
import org.armgals.gals.Island;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.KernelOptions;
import org.armgals.kernel.NotificationPolicy;
import org.armgals.kernel.ReflectionEvent;
import org.armgals.kernel.StructuralMeta;
import org.armgals.kernel.spi.ReflectionListener;
import org.armgals.representation.p.PState;

/**
 * The main class of an atom's JVM in {@link Distributed}: joins the broker through its own {@link
 * JmsTransport}, runs the atom's {@link DistributedCrawler} on an island of its own, started on
 * real time, and leaves when its standard input ends (the world closes it, or ends).
 *
 * <p>The robot is a kernel entity of the atom's runtime: the world sends it its readings as
 * stimuli, which its {@code receive} schema feeds to the body at each release, and its {@code
 * report} schema sends the world the commands of the cycle before, if they answer new readings. It
 * is started with no behavioral meta of its own: its runtime registers it under its name in the
 * broker's name service, and the meta level, in the world's JVM, takes it from there; it notifies
 * its states (the battery's fraction and its swing only) and the threshold meta-event {@link
 * DistributedCrawler#LOW_BATTERY}. The atom's kernel tells time in the world's time of the last
 * readings, which its notifications carry. It tells the world it has joined once started.
 *
 * <p>Arguments: atom id, index in the chain, atoms in the chain, broker URL, topic prefix, the
 * world's address (runtime and id), the island's period in nanoseconds, the battery's capacity in
 * J, the file its robot's side of the reflective loop's record goes to when it leaves. The broker's
 * credentials, if any, come in the environment ({@value BrokerLogin#USER}, {@value
 * BrokerLogin#PASSWORD}).
 */
final class DistributedAtomMain {

  private DistributedAtomMain() {}

  static List<String> args(
      int atom,
      int index,
      int count,
      String url,
      String prefix,
      Address world,
      Duration period,
      double capacity,
      Path loop) {
    return List.of(
        Integer.toString(atom),
        Integer.toString(index),
        Integer.toString(count),
        url,
        prefix,
        world.runtime(),
        Long.toString(world.id()),
        Long.toString(period.toNanos()),
        Double.toString(capacity),
        loop.toAbsolutePath().toString());
  }

  public static void main(String[] args) throws IOException {
    if (args.length != 10) {
      System.err.println(
          "expected 10 arguments (see DistributedAtomMain's javadoc), got " + args.length);
      System.exit(2);
    }
    int atom = Integer.parseInt(args[0]);
    int index = Integer.parseInt(args[1]);
    int count = Integer.parseInt(args[2]);
    String url = args[3];
    String prefix = args[4];
    Address world = new Address(args[5], Long.parseLong(args[6]));
    Duration period = Duration.ofNanos(Long.parseLong(args[7]));
    double capacity = Double.parseDouble(args[8]);
    Path loopFile = Path.of(args[9]);
    long pid = ProcessHandle.current().pid();
    String name = "atom" + atom + "-" + pid;
    JmsTransport.Builder builder =
        BrokerLogin.fromEnvironment()
            .on(
                Kernel.allowKernelEvents(
                    JmsTransport.builder().prefix(prefix).allow(DistributedWire.ALLOWED)),
                url);
    DistributedRemoteBody body = new DistributedRemoteBody(atom);
    Notified notified = new Notified(DistributedCrawler.robotName(atom));
    // The robot's side of the loop, at the world's cycle of the last readings.
    LoopRecord loop =
        new LoopRecord(
                period.toNanos(), () -> Math.max(0, body.worldTimeNanos()) / period.toNanos())
            .watch(DistributedCrawler.robotName(atom));
    try (JmsTransport transport = builder.build()) {
      ActiveRuntime runtime =
          ActiveRuntime.builder().name(name).workers(1).jmx(false).transport(transport).build();
      try (Kernel kernel =
              org.armgals.kernel.StructuralMeta.bootstrap(
                  runtime,
                  KernelOptions.defaults()
                      .withJmx(false)
                      .withTimeSource(() -> Math.max(0, body.worldTimeNanos()))
                      .withListener(
                          event -> {
                            notified.on(event);
                            loop.on(event);
                          }));
          Island island =
              Island.builder("atom" + atom, runtime).period(period).jmx(false).build()) {
        DistributedCrawler[] self = new DistributedCrawler[1];
        DistributedCrawler robot =
            new DistributedCrawler(
                body,
                index,
                count,
                capacity,
                notified::last,
                payload ->
                    runtime.ref(world).send(new Emission(self[0].address(), world, payload)));
        self[0] = robot;
        StructuralMeta<PState> kind = DistributedCrawler.kind(kernel);
        // No meta of its own: the meta level, in the world's JVM, takes it by its name.
        robot.start(
            island,
            kind,
            island
                .entityOptions()
                .withNotification(
                    NotificationPolicy.statesOnly()
                        .observing(DistributedCrawler.FRACTION, DistributedCrawler.SWING)
                        .watching(DistributedCrawler.LOW_BATTERY)));
        transport.register(robot.name(), robot.address());
        runtime
            .ref(world)
            .send(
                new Emission(
                    robot.address(),
                    world,
                    new DistributedWire.Joined(atom, robot.address(), pid, name)));
        island.start();
        System.out.println(
            "atom " + atom + " runs on island " + island.name() + " of runtime " + name);
        InputStream in = System.in;
        while (in.read() != -1) {
          // The world says nothing on this pipe: its end is the signal to leave.
        }
        loop.write(loopFile);
        System.out.println(
            "atom "
                + atom
                + " leaves after "
                + robot.cycles()
                + " cycles, "
                + notified.last()
                + " notifications, request "
                + robot.appliedVersion()
                + " applied last, "
                + island.stats());
      } finally {
        runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5));
      }
    }
  }

  /**
   * The number of the last notification the robot's entity sent its behavioral meta, as the atom's
   * kernel tells it: on the robot's thread, during its cycle.
   */
  private static final class Notified implements ReflectionListener {
    private final String robot;
    private volatile long last;

    Notified(String robot) {
      this.robot = robot;
    }

    @Override
    public void on(ReflectionEvent event) {
      if (event instanceof ReflectionEvent.Notified n && n.entity().equals(robot)) {
        last = n.notification().seq();
      }
    }

    long last() {
      return last;
    }
  }
}

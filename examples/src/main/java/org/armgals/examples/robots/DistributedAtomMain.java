package org.armgals.examples.robots;

import java.io.IOException;
import java.io.InputStream;
import java.time.Duration;
import java.util.List;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.ShutdownMode;
import org.armgals.active.jms.JmsTransport;
import org.armgals.gals.Emission;
import org.armgals.gals.Island;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.KernelOptions;
import org.armgals.kernel.StructuralMeta;
import org.armgals.maam.RobotKind;
import org.armgals.representation.p.PState;

/**
 * The main class of an atom's JVM in {@link Distributed}: joins the broker through its own {@link
 * JmsTransport}, runs the atom's {@link DistributedCrawler} on an island of its own, started on
 * real time, and leaves when its standard input ends (the world closes it, or ends).
 *
 * <p>The robot is a kernel entity of the atom's runtime: the world sends it its readings as
 * stimuli, which its {@code receive} schema feeds to the body at each release, and its {@code
 * report} schema sends the world the commands of the cycle just run, if they answer new readings.
 * It tells the world it has joined once started.
 *
 * <p>Arguments: atom id, index in the chain, atoms in the chain, broker URL, topic prefix, the
 * world's address (runtime and id), the island's period in nanoseconds. The broker's credentials,
 * if any, come in the environment ({@value #USER}, {@value #PASSWORD}).
 */
final class DistributedAtomMain {
  static final String USER = "ARMGALS_BROKER_USER";
  static final String PASSWORD = "ARMGALS_BROKER_PASSWORD";

  private DistributedAtomMain() {}

  static List<String> args(
      int atom, int index, int count, String url, String prefix, Address world, Duration period) {
    return List.of(
        Integer.toString(atom),
        Integer.toString(index),
        Integer.toString(count),
        url,
        prefix,
        world.runtime(),
        Long.toString(world.id()),
        Long.toString(period.toNanos()));
  }

  public static void main(String[] args) throws IOException {
    if (args.length != 8) {
      System.err.println(
          "expected 8 arguments (see DistributedAtomMain's javadoc), got " + args.length);
      System.exit(2);
    }
    int atom = Integer.parseInt(args[0]);
    int index = Integer.parseInt(args[1]);
    int count = Integer.parseInt(args[2]);
    String url = args[3];
    String prefix = args[4];
    Address world = new Address(args[5], Long.parseLong(args[6]));
    Duration period = Duration.ofNanos(Long.parseLong(args[7]));
    long pid = ProcessHandle.current().pid();
    String name = "atom" + atom + "-" + pid;
    String user = System.getenv(USER);
    JmsTransport.Builder builder =
        Kernel.allowKernelEvents(
            JmsTransport.builder().prefix(prefix).allow(DistributedWire.ALLOWED));
    if (user == null) {
      builder.broker(url);
    } else {
      String password = System.getenv(PASSWORD);
      builder.broker(url, user, password == null ? "" : password);
    }
    try (JmsTransport transport = builder.build()) {
      ActiveRuntime runtime =
          ActiveRuntime.builder().name(name).workers(1).jmx(false).transport(transport).build();
      try (Kernel kernel =
              org.armgals.kernel.StructuralMeta.bootstrap(
                  runtime, KernelOptions.defaults().withJmx(false));
          Island island =
              Island.builder("atom" + atom, runtime).period(period).jmx(false).build()) {
        DistributedRemoteBody body = new DistributedRemoteBody(atom);
        DistributedCrawler[] self = new DistributedCrawler[1];
        DistributedCrawler robot =
            new DistributedCrawler(
                body,
                index,
                count,
                payload ->
                    runtime.ref(world).send(new Emission(self[0].address(), world, payload)));
        self[0] = robot;
        StructuralMeta<PState> kind =
            RobotKind.define(kernel, "DistributedCrawler", robot.observation());
        robot.start(island, kind, kernel.basicBehavioralMeta(), island.entityOptions());
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
        System.out.println(
            "atom " + atom + " leaves after " + robot.cycles() + " cycles, " + island.stats());
      } finally {
        runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5));
      }
    }
  }
}

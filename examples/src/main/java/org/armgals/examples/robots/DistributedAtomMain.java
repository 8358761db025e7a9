package org.armgals.examples.robots;

import java.io.IOException;
import java.io.InputStream;
import java.time.Duration;
import java.util.List;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.JmsTransport;
import org.armgals.active.ShutdownMode;
import org.armgals.gals.Island;
import org.armgals.gals.ReactiveEntity;
import org.armgals.maam.AbstractRobot;

/**
 * The main class of an atom's JVM in {@link Distributed}: joins the broker through its own {@link
 * JmsTransport}, runs the atom's {@link DistributedCrawler} on an island of its own, started on
 * real time, and leaves when its standard input ends (the world closes it, or ends).
 *
 * <p>The robot's entity has a second reaction, {@code link}, that runs after the robot's cycle in
 * every release: it feeds the readings taken at the release to the body, for the robot's next
 * cycle, and sends the world the commands of the cycle just run, if they answer new readings (and,
 * once, that the atom has joined).
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
        JmsTransport.builder().prefix(prefix).allow(DistributedWire.ALLOWED);
    if (user == null) {
      builder.broker(url);
    } else {
      String password = System.getenv(PASSWORD);
      builder.broker(url, user, password == null ? "" : password);
    }
    try (JmsTransport transport = builder.build()) {
      ActiveRuntime runtime =
          ActiveRuntime.builder().name(name).workers(1).jmx(false).transport(transport).build();
      try (Island island =
          Island.builder("atom" + atom, runtime).period(period).jmx(false).build()) {
        DistributedRemoteBody body = new DistributedRemoteBody(atom);
        DistributedCrawler robot = new DistributedCrawler(body, index, count);
        ReactiveEntity<AbstractRobot> entity = robot.start(island);
        entity.addReaction(
            "link",
            new DistributedLink(
                world, body, new DistributedWire.Joined(atom, entity.address(), pid, name)));
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

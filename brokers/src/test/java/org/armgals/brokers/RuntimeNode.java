package org.armgals.brokers;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.armgals.active.ActiveObject;
import org.armgals.active.ActiveRef;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.Address;
import org.armgals.active.Event;
import org.armgals.active.EventProcessor;
import org.armgals.active.FutureTimeoutException;
import org.armgals.active.Request;
import org.armgals.active.TimeSource;
import org.armgals.active.jms.JmsTransport;
import org.armgals.active.jms.Presence;
import org.jspecify.annotations.Nullable;

/**
 * A runtime JVM of the multi-JVM tests, started by them as a child process on the test class path.
 * It connects to the broker named by the environment ({@code ARMGALS_BROKER_URL}, {@code
 * ARMGALS_BROKER_USER}, {@code ARMGALS_BROKER_PASSWORD}, {@code ARMGALS_PREFIX}: credentials stay
 * out of the command line), beats on the broker ({@link Presence}, as runtime {@code <role>-<pid>})
 * and plays one role:
 *
 * <ul>
 *   <li>{@code serve}: spawns a {@link Counter}, registers it as {@code counter}, prints {@code
 *       ready runtime=<name> at=<address>}, and runs until its standard input ends (then says it
 *       leaves);
 *   <li>{@code ask <n>}: looks {@code counter} up, sends it {@code n} {@link Ping}s, asks it for
 *       its {@link Count} and a {@link Sum}, prints {@code result count=<c> sum=<s> at=<address>}
 *       and exits.
 * </ul>
 */
public final class RuntimeNode {
  static final Duration WAIT = Duration.ofSeconds(30);

  /** How often a node beats; four missed beats make it lost. */
  static final Duration PRESENCE_PERIOD = Duration.ofMillis(200);

  private RuntimeNode() {}

  /** A one-way event. */
  public record Ping(@Nullable Address sender, Address destination, long n) implements Event {}

  /** How many pings the counter has processed. */
  public record Count(@Nullable Address sender, Address destination) implements Request<Long> {}

  /** The sum of two numbers. */
  public record Sum(@Nullable Address sender, Address destination, int a, int b)
      implements Request<Integer> {}

  static final Class<?>[] ALLOWED = {Ping.class, Count.class, Sum.class};

  /** Counts pings, answers counts and sums. */
  public static final class Counter implements EventProcessor {
    private long pings;

    @Override
    public void process(Event event) {
      if (!(event instanceof Ping)) {
        throw new IllegalArgumentException("expected a Ping, was " + event);
      }
      pings++;
    }

    @Override
    public Object answer(Request<?> request) {
      return switch (request) {
        case Count c -> pings;
        case Sum s -> s.a() + s.b();
        default -> throw new IllegalArgumentException("expected a Count or a Sum, was " + request);
      };
    }
  }

  /**
   * Starts a runtime JVM playing {@code args} against {@code broker}, under {@code prefix}, on the
   * test class path and the tests' JDK; its output goes to {@code <name>.log} beside the broker.
   */
  static ChildProcess launch(
      StandaloneBroker broker, String name, String prefix, List<String> args) {
    ProcessBuilder command =
        new ProcessBuilder(
            Path.of(System.getProperty("java.home"), "bin", "java").toString(),
            "-Xmx256m",
            "-XX:TieredStopAtLevel=1",
            "-cp",
            System.getProperty("java.class.path"),
            RuntimeNode.class.getName());
    command.command().addAll(args);
    command.environment().put("ARMGALS_BROKER_URL", broker.url());
    command.environment().put("ARMGALS_BROKER_USER", broker.spec().user().user());
    command.environment().put("ARMGALS_BROKER_PASSWORD", broker.spec().user().password());
    command.environment().put("ARMGALS_PREFIX", prefix);
    return ChildProcess.start(
        name, command, broker.instance().getParent().resolve(name + ".log"), TimeSource.system());
  }

  /**
   * Asks {@code remote} for sums until one is answered, or throws at {@code timeout}. After a
   * broker restart, or across the brokers of a cluster, subscriptions come back or across
   * asynchronously, and a request sent before they have is lost and fails at its reply timeout.
   */
  static void awaitAnswer(ActiveRef<Counter> remote, Address at, Duration timeout) {
    TimeSource time = TimeSource.system();
    long deadline = time.nanoTime() + timeout.toNanos();
    FutureTimeoutException last = null;
    while (time.nanoTime() - deadline < 0) {
      try {
        if (remote.ask(new Sum(null, at, 2, 3)).getValue(WAIT) == 5) {
          return;
        }
      } catch (FutureTimeoutException e) {
        last = e;
      }
    }
    throw new IllegalStateException("no answer crossed the broker within " + timeout, last);
  }

  static JmsTransport.Builder transport(String url, String user, String password, String prefix) {
    return JmsTransport.builder().broker(url, user, password).prefix(prefix).allow(ALLOWED);
  }

  static ActiveRuntime runtime(String name, JmsTransport transport) {
    return ActiveRuntime.builder().name(name).workers(2).jmx(false).transport(transport).build();
  }

  /** Entry point; see the class comment. */
  public static void main(String[] args) throws Exception {
    String role = args.length > 0 ? args[0] : "";
    String name = role + "-" + ProcessHandle.current().pid();
    try (Presence presence =
            Presence.builder()
                .broker(
                    env("ARMGALS_BROKER_URL"),
                    env("ARMGALS_BROKER_USER"),
                    env("ARMGALS_BROKER_PASSWORD"))
                .prefix(env("ARMGALS_PREFIX"))
                .runtime(name)
                .period(PRESENCE_PERIOD)
                .build();
        JmsTransport transport =
            transport(
                    env("ARMGALS_BROKER_URL"),
                    env("ARMGALS_BROKER_USER"),
                    env("ARMGALS_BROKER_PASSWORD"),
                    env("ARMGALS_PREFIX"))
                .build();
        ActiveRuntime runtime = runtime(presence.runtime(), transport)) {
      switch (role) {
        case "serve" -> serve(transport, runtime);
        case "ask" -> ask(transport, runtime, Integer.parseInt(args[1]));
        default ->
            throw new IllegalArgumentException("role must be serve or ask, was '" + role + "'");
      }
    }
    System.exit(0);
  }

  private static void serve(JmsTransport transport, ActiveRuntime runtime) throws Exception {
    ActiveObject<Counter> counter = runtime.spawn(new Counter());
    transport.register("counter", counter.address());
    System.out.println("ready runtime=" + runtime.name() + " at=" + counter.address());
    System.out.flush();
    BufferedReader in =
        new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
    while (in.readLine() != null) {
      // Runs until the test closes standard input (or kills this JVM).
    }
  }

  private static void ask(JmsTransport transport, ActiveRuntime runtime, int n) {
    Address at = transport.lookup("counter").getValue(WAIT);
    ActiveRef<Counter> counter = runtime.ref(at);
    for (int i = 0; i < n; i++) {
      counter.send(new Ping(null, at, i));
    }
    long count = counter.ask(new Count(null, at)).getValue(WAIT);
    int sum = counter.ask(new Sum(null, at, 20, 22)).getValue(WAIT);
    System.out.println("result count=" + count + " sum=" + sum + " at=" + at);
    System.out.flush();
  }

  private static String env(String name) {
    String value = System.getenv(name);
    if (value == null || value.isBlank()) {
      throw new IllegalStateException("environment variable " + name + " must be set");
    }
    return value;
  }
}

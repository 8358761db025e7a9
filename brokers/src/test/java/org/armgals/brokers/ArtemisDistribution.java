package org.armgals.brokers;

import static java.util.Objects.requireNonNull;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import org.armgals.active.TimeSource;

/**
 * The unpacked Apache Artemis distribution (the build unpacks {@code
 * org.apache.artemis:apache-artemis:tar.gz:bin} into {@code target/}) and the JDK it runs on;
 * creates broker instances with {@code artemis create}.
 *
 * <p>The system properties, set by the module's Surefire configuration: {@value #HOME} (the
 * distribution), {@value #JAVA_HOME} (the JDK for the broker; blank means the JDK these tests run
 * on, which is the toolchain JDK the build selected) and {@value #BROKERS_DIR} (where instances are
 * created).
 */
final class ArtemisDistribution {
  static final String HOME = "armgals.artemis.home";
  static final String JAVA_HOME = "armgals.artemis.javaHome";
  static final String BROKERS_DIR = "armgals.brokers.dir";

  /**
   * The broker JVM's options, in place of the instance profile's (whose -Xms is larger than its
   * -Xmx on this JDK): a small heap and the client compiler only, since two brokers and two
   * runtimes may share two cores with the build.
   */
  static final String BROKER_JAVA_ARGS =
      "-Xms64m -Xmx384m -XX:+UseSerialGC -XX:TieredStopAtLevel=1 -Dlog4j2.disableJmx=true"
          + " --add-opens java.base/jdk.internal.misc=ALL-UNNAMED";

  private static final Duration CREATE_TIMEOUT = Duration.ofSeconds(60);

  private final Path home;
  private final Path javaHome;
  private final Path brokersDir;
  private final TimeSource time;

  ArtemisDistribution(Path home, Path javaHome, Path brokersDir, TimeSource time) {
    this.home = requireExecutable(home.resolve("bin/artemis"), HOME).getParent().getParent();
    this.javaHome =
        requireExecutable(javaHome.resolve("bin/java"), JAVA_HOME).getParent().getParent();
    this.brokersDir = requireNonNull(brokersDir, "brokersDir");
    this.time = requireNonNull(time, "time");
  }

  /** The distribution named by the system properties (see the class comment). */
  static ArtemisDistribution fromSystemProperties() {
    String home = System.getProperty(HOME, "");
    if (home.isBlank()) {
      throw new IllegalStateException(
          "system property "
              + HOME
              + " must name the unpacked Artemis distribution; run the"
              + " tests through Maven, which unpacks it and sets the property");
    }
    String javaHome = System.getProperty(JAVA_HOME, "");
    if (javaHome.isBlank()) {
      javaHome = System.getProperty("java.home");
    }
    String brokers = System.getProperty(BROKERS_DIR, "");
    Path brokersDir = brokers.isBlank() ? Path.of("target", "brokers") : Path.of(brokers);
    return new ArtemisDistribution(
        Path.of(home), Path.of(javaHome), brokersDir, TimeSource.system());
  }

  private static Path requireExecutable(Path file, String property) {
    if (!Files.isRegularFile(file)) {
      throw new IllegalArgumentException(
          file + " does not exist; expected " + property + " to name a directory holding it");
    }
    return file.toAbsolutePath();
  }

  Path javaHome() {
    return javaHome;
  }

  /** Creates (does not start) a fresh broker instance in a new directory under the brokers dir. */
  StandaloneBroker create(BrokerSpec spec) throws InterruptedException {
    requireNonNull(spec, "spec");
    Path dir;
    try {
      Files.createDirectories(brokersDir);
      dir = Files.createTempDirectory(brokersDir.toAbsolutePath(), spec.name() + "-");
    } catch (IOException e) {
      throw new UncheckedIOException("cannot make a directory for broker " + spec.name(), e);
    }
    Path instance = dir.resolve("instance");
    ProcessBuilder command = command(home.resolve("bin/artemis"), createArguments(spec, instance));
    try (ChildProcess create =
        ChildProcess.start(
            "artemis create " + spec.name(), command, dir.resolve("create.log"), time)) {
      int code = create.awaitExit(CREATE_TIMEOUT);
      if (code != 0) {
        throw new IllegalStateException(
            "artemis create " + spec.name() + " exited with " + code + ":\n" + create.tail());
      }
    }
    return new StandaloneBroker(spec, instance, this, time);
  }

  /** {@code bash script args...}, with the broker's JDK and options in the environment. */
  ProcessBuilder command(Path script, List<String> args) {
    List<String> command = new ArrayList<>(List.of("bash", script.toString()));
    command.addAll(args);
    ProcessBuilder builder = new ProcessBuilder(command);
    builder.environment().keySet().removeIf(name -> name.startsWith("ARTEMIS_"));
    builder.environment().put("JAVA_HOME", javaHome.toString());
    builder.environment().put("JAVA_ARGS", BROKER_JAVA_ARGS);
    return builder;
  }

  private static List<String> createArguments(BrokerSpec spec, Path instance) {
    List<String> args = new ArrayList<>();
    args.addAll(
        List.of(
            "create",
            instance.toString(),
            "--silent",
            "--name",
            spec.name(),
            "--host",
            "127.0.0.1",
            "--default-port",
            Integer.toString(spec.port()),
            "--require-login",
            "--user",
            spec.user().user(),
            "--password",
            spec.user().password(),
            "--no-web",
            "--http-host",
            "127.0.0.1",
            "--no-amqp-acceptor",
            "--no-mqtt-acceptor",
            "--no-stomp-acceptor",
            "--no-hornetq-acceptor",
            "--no-autotune",
            "--nio"));
    if (!spec.persistent()) {
      args.add("--disable-persistence");
    }
    spec.cluster()
        .ifPresent(
            cluster ->
                args.addAll(
                    List.of(
                        "--clustered",
                        "--cluster-user",
                        cluster.clusterUser().user(),
                        "--cluster-password",
                        cluster.clusterUser().password(),
                        "--staticCluster",
                        cluster.peerPorts().stream()
                            .map(port -> "tcp://127.0.0.1:" + port)
                            .collect(Collectors.joining(",")),
                        "--message-load-balancing",
                        "ON_DEMAND",
                        "--max-hops",
                        "1")));
    return args;
  }
}

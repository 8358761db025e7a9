package org.armgals.brokers;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.armgals.active.TimeSource;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The standalone broker and two runtime JVMs started from the test: one serves a counter under a
 * name, the other looks it up, sends it events and asks it questions (futures across JVMs).
 */
class MultiJvmTest {
  private static final Duration WAIT = Duration.ofSeconds(60);

  @RegisterExtension static final BrokerExtension BROKERS = BrokerExtension.standalone("multi");

  /** A runtime JVM playing {@code args} against the broker, under {@code prefix}. */
  static ChildProcess node(String name, String prefix, List<String> args) {
    StandaloneBroker broker = BROKERS.broker();
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

  @Test
  void twoRuntimeJvmsExchangeEventsFuturesAndNameLookUpsThroughTheStandaloneBroker()
      throws Exception {
    try (ChildProcess server = node("server", "multi", List.of("serve"))) {
      String ready = server.awaitLine("ready", line -> line.startsWith("ready "), WAIT);
      String address = ready.substring("ready ".length());

      try (ChildProcess asker = node("asker", "multi", List.of("ask", "1000"))) {
        String result = asker.awaitLine("result", line -> line.startsWith("result "), WAIT);

        assertThat(result).isEqualTo("result count=1000 sum=42 at=" + address);
        assertThat(asker.awaitExit(WAIT)).isZero();
      }
      assertThat(server.isAlive()).isTrue();
    }
  }
}

package org.armgals.brokers;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The standalone broker and two runtime JVMs started from the test: one serves a counter under a
 * name, the other looks it up, sends it events and asks it questions (futures across JVMs).
 */
class MultiJvmTest {
  private static final Duration WAIT = Duration.ofSeconds(60);

  @RegisterExtension static final BrokerExtension BROKERS = BrokerExtension.standalone("multi");

  @Test
  void twoRuntimeJvmsExchangeEventsFuturesAndNameLookUpsThroughTheStandaloneBroker()
      throws Exception {
    try (ChildProcess server =
        RuntimeNode.launch(BROKERS.broker(), "server", "multi", List.of("serve"))) {
      String ready = server.awaitLine("ready", line -> line.startsWith("ready "), WAIT);
      String address = ready.substring(ready.indexOf(" at=") + " at=".length());

      try (ChildProcess asker =
          RuntimeNode.launch(BROKERS.broker(), "asker", "multi", List.of("ask", "1000"))) {
        String result = asker.awaitLine("result", line -> line.startsWith("result "), WAIT);

        assertThat(result).isEqualTo("result count=1000 sum=42 at=" + address);
        assertThat(asker.awaitExit(WAIT)).isZero();
      }
      assertThat(server.isAlive()).isTrue();
    }
  }
}

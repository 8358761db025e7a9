package org.armgals.gals;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.management.ManagementFactory;
import java.time.Duration;
import javax.management.MBeanServer;
import javax.management.ObjectName;
import org.armgals.active.ActiveRuntime;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

class IslandJmxTest {
  private final ActiveRuntime runtime = Fixtures.runtime("jmx-test", 1);

  @AfterEach
  void close() {
    runtime.close();
  }

  @Test
  void islandPublishesItsFiguresOverJmxWhileOpen() throws Exception {
    MBeanServer server = ManagementFactory.getPlatformMBeanServer();
    ObjectName name = new ObjectName("org.armgals:type=Island,runtime=\"jmx-test\",name=\"i\"");
    FakeTime time = new FakeTime();
    try (Island island =
        Island.builder("i", runtime)
            .period(Duration.ofMillis(10))
            .timeSource(time)
            .jmx(true)
            .build()) {
      island.spawn("e", 0, c -> time.advance(Duration.ofMillis(c.instant() == 2 ? 12 : 1)));
      island.step(3);

      assertThat(server.getAttribute(name, "Instants")).isEqualTo(3L);
      assertThat(server.getAttribute(name, "Overruns")).isEqualTo(1L);
      assertThat(server.getAttribute(name, "CycleMaxNanos")).isEqualTo(12_000_000L);
      assertThat(server.getAttribute(name, "Entities")).isEqualTo(1);
    }
    assertThat(server.isRegistered(name)).isFalse();
  }

  @Test
  void islandWithoutJmxRegistersNothing() {
    try (Island island = Island.builder("quiet", runtime).jmx(false).build()) {
      assertThat(island.name()).isEqualTo("quiet");
      assertThat(
              ManagementFactory.getPlatformMBeanServer().queryNames(null, null).stream()
                  .anyMatch(
                      n ->
                          "Island".equals(n.getKeyProperty("type"))
                              && "\"quiet\"".equals(n.getKeyProperty("name"))))
          .isFalse();
    }
  }
}

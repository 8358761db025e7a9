package org.armgals.kernel;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.management.ManagementFactory;
import java.time.Duration;
import java.util.Map;
import javax.management.JMX;
import javax.management.MBeanServer;
import org.armgals.active.ActiveRuntime;
import org.armgals.active.ShutdownMode;
import org.junit.jupiter.api.Test;

/** Entities and models over JMX. */
class JmxTest {

  @Test
  void entitiesAndModelsAreVisibleOverJmxUntilTheKernelCloses() throws Exception {
    ManualTime time = new ManualTime();
    MBeanServer server = ManagementFactory.getPlatformMBeanServer();
    try (ActiveRuntime runtime =
        ActiveRuntime.builder().name("jmx-test").workers(1).jmx(false).build()) {
      Kernel kernel =
          StructuralMeta.bootstrap(runtime, KernelOptions.defaults().withTimeSource(time));
      BehavioralMeta meta = kernel.newBehavioralMeta("meta", new Recorder(), Damping.none());
      Entity robot =
          kernel
              .newStructuralMeta("Robot", KernelFixture.ROBOT, KernelFixture.robotBehaviors())
              .newEntity("robot", meta);
      meta.setFilter(robot, "kind = 'state'").touch();
      robot.call("work", 0.5).getValue();
      KernelFixture.drain(meta);
      time.advance(Duration.ofSeconds(2));

      EntityMXBean entity =
          JMX.newMXBeanProxy(server, Jmx.name("jmx-test", "Entity", "robot"), EntityMXBean.class);
      assertThat(entity.getState()).contains("battery=0.5");
      assertThat(entity.getStructuralMeta()).isEqualTo("Robot");
      assertThat(entity.getBehavioralMeta()).isEqualTo("meta");
      assertThat(entity.getBehaviors()).contains("work", "charge");

      BehavioralMetaMXBean model =
          JMX.newMXBeanProxy(
              server, Jmx.name("jmx-test", "BehavioralMeta", "meta"), BehavioralMetaMXBean.class);
      assertThat(model.getModels().get("robot")).contains("battery=0.5");
      assertThat(model.getStalenessMillis()).isEqualTo(Map.of("robot", 2000L));
      assertThat(model.getFilters()).isEqualTo(Map.of("robot", "kind = 'state'"));
      assertThat(model.getLost()).isEqualTo(Map.of("robot", false));

      kernel.close();
      assertThat(server.isRegistered(Jmx.name("jmx-test", "Entity", "robot"))).isFalse();
      runtime.shutdown(ShutdownMode.CANCEL, Duration.ofSeconds(5));
    }
  }
}

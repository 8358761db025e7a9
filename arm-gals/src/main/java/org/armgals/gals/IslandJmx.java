package org.armgals.gals;

import java.lang.management.ManagementFactory;
import javax.management.JMException;
import javax.management.ObjectName;
import javax.management.StandardMBean;
import org.jspecify.annotations.Nullable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** Registers an island's figures over JMX, and unregisters them; a failure only logs. */
final class IslandJmx {
  private static final Logger LOG = LoggerFactory.getLogger(IslandJmx.class);

  private IslandJmx() {}

  static @Nullable ObjectName register(IslandImpl island, String runtime) {
    try {
      ObjectName on =
          new ObjectName(
              "org.armgals:type=Island,runtime="
                  + ObjectName.quote(runtime)
                  + ",name="
                  + ObjectName.quote(island.name()));
      ManagementFactory.getPlatformMBeanServer()
          .registerMBean(new StandardMBean(new Figures(island), IslandMXBean.class, true), on);
      return on;
    } catch (JMException e) {
      LOG.warn(
          "island {}: its MBean could not be registered; figures stay in stats()",
          island.name(),
          e);
      return null;
    }
  }

  static void unregister(@Nullable ObjectName on, String island) {
    if (on != null) {
      try {
        ManagementFactory.getPlatformMBeanServer().unregisterMBean(on);
      } catch (JMException e) {
        LOG.warn("island {}: its MBean could not be unregistered", island, e);
      }
    }
  }

  /** The MBean: reads the island's stats. */
  private record Figures(IslandImpl island) implements IslandMXBean {
    @Override
    public String getName() {
      return island.name();
    }

    @Override
    public long getPeriodNanos() {
      return island.period().toNanos();
    }

    @Override
    public long getInstants() {
      return island.stats().instants();
    }

    @Override
    public long getOverruns() {
      return island.stats().overruns();
    }

    @Override
    public long getSkipped() {
      return island.stats().skipped();
    }

    @Override
    public long getMeanPeriodNanos() {
      return island.stats().meanPeriod().toNanos();
    }

    @Override
    public long getJitterP50Nanos() {
      return island.stats().jitterP50().toNanos();
    }

    @Override
    public long getJitterP99Nanos() {
      return island.stats().jitterP99().toNanos();
    }

    @Override
    public long getJitterMaxNanos() {
      return island.stats().jitterMax().toNanos();
    }

    @Override
    public long getCycleMaxNanos() {
      return island.stats().cycleMax().toNanos();
    }

    @Override
    public long getAdaptations() {
      return island.stats().adaptations();
    }

    @Override
    public long getAdaptationOverruns() {
      return island.stats().adaptationOverruns();
    }

    @Override
    public long getFailures() {
      return island.stats().failures();
    }

    @Override
    public int getEntities() {
      return island.entities().size();
    }
  }
}

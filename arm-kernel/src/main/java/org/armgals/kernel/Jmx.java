package org.armgals.kernel;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.management.JMException;
import javax.management.MBeanServer;
import javax.management.ObjectName;
import org.armgals.active.Address;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** Registers the MBeans of a kernel's entities and behavioral metas, and unregisters them. */
final class Jmx {
  private static final Logger LOG = LoggerFactory.getLogger(Jmx.class);

  private final String runtime;
  private final boolean enabled;
  private final List<ObjectName> registered = new ArrayList<>();

  Jmx(String runtime, boolean enabled) {
    this.runtime = runtime;
    this.enabled = enabled;
  }

  static ObjectName name(String runtime, String type, String entity) throws JMException {
    return new ObjectName(
        "org.armgals.kernel:type="
            + type
            + ",runtime="
            + ObjectName.quote(runtime)
            + ",name="
            + ObjectName.quote(entity));
  }

  synchronized void register(EntityImpl<?> e) {
    if (!enabled) {
      return;
    }
    MBeanServer server = ManagementFactory.getPlatformMBeanServer();
    try {
      ObjectName n = name(runtime, "Entity", e.name());
      server.registerMBean(new EntityBean(e), n);
      registered.add(n);
      if (e instanceof BehavioralMetaImpl m) {
        ObjectName mn = name(runtime, "BehavioralMeta", e.name());
        server.registerMBean(new MetaBean(m), mn);
        registered.add(mn);
      }
    } catch (JMException ex) {
      LOG.warn("could not register the MBean of entity {}", e, ex);
    }
  }

  synchronized void close() {
    MBeanServer server = ManagementFactory.getPlatformMBeanServer();
    for (ObjectName n : registered) {
      try {
        server.unregisterMBean(n);
      } catch (JMException ex) {
        LOG.warn("could not unregister {}", n, ex);
      }
    }
    registered.clear();
  }

  private record EntityBean(EntityImpl<?> e) implements EntityMXBean {
    @Override
    public String getName() {
      return e.name();
    }

    @Override
    public String getAddress() {
      return e.address().toString();
    }

    @Override
    public String getStructuralMeta() {
      return e.structuralMeta().name();
    }

    @Override
    public String getBehavioralMeta() {
      return e.behavioralMeta().map(Entity::name).orElse("");
    }

    @Override
    public String getState() {
      return e.state().observe().toString();
    }

    @Override
    public String[] getBehaviors() {
      return e.servant.behaviors().names().toArray(String[]::new);
    }

    @Override
    public String getNotificationPolicy() {
      return e.notificationPolicy().toString();
    }

    @Override
    public long getAppliedVersion() {
      return e.appliedVersion();
    }

    @Override
    public long getAdaptationOverruns() {
      return e.servant.adaptationOverruns();
    }

    @Override
    public long getAdaptationMaxNanos() {
      return e.servant.adaptationMaxNanos();
    }

    @Override
    public long getLockStepTimeouts() {
      return e.servant.lockStepTimeouts();
    }

    @Override
    public int getQueueDepth() {
      return e.queueDepth();
    }
  }

  record MetaBean(BehavioralMetaImpl m) implements BehavioralMetaMXBean {
    @Override
    public Map<String, String> getModels() {
      return m.modelStates();
    }

    @Override
    public Map<String, Long> getStalenessMillis() {
      Map<String, Long> r = new LinkedHashMap<>();
      long now = m.kernel.nanoTime();
      eachPublished((name, p) -> r.put(name, p.staleness(now).toMillis()));
      return r;
    }

    @Override
    public Map<String, String> getFilters() {
      Map<String, String> r = new LinkedHashMap<>();
      each((name, v) -> r.put(name, v.filter()));
      return r;
    }

    @Override
    public Map<String, Long> getAppliedVersions() {
      Map<String, Long> r = new LinkedHashMap<>();
      each((name, v) -> r.put(name, v.appliedVersion()));
      return r;
    }

    @Override
    public Map<String, Boolean> getLost() {
      Map<String, Boolean> r = new LinkedHashMap<>();
      each((name, v) -> r.put(name, v.lost()));
      return r;
    }

    @Override
    public long getSuppressedAdaptations() {
      return m.suppressed();
    }

    private void each(java.util.function.BiConsumer<String, ModelView> f) {
      eachPublished((name, p) -> f.accept(name, p.view()));
    }

    private void eachPublished(
        java.util.function.BiConsumer<String, BehavioralMetaImpl.Published> f) {
      for (Entity b : m.baseLevelEntities()) {
        Address a = b.address();
        BehavioralMetaImpl.Published p = m.views.get(a);
        if (p != null) {
          f.accept(b.name(), p);
        }
      }
    }
  }
}

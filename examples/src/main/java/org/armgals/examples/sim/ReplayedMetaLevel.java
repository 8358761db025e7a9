package org.armgals.examples.sim;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.armgals.active.Address;
import org.armgals.examples.run.Summary;
import org.armgals.kernel.Adaptation;
import org.armgals.kernel.Damping;
import org.armgals.kernel.Kernel;
import org.armgals.kernel.Notification;
import org.armgals.kernel.StructuralMeta;
import org.armgals.kernel.spi.MetaContext;
import org.armgals.maam.BMetaRobot;
import org.armgals.representation.p.PState;

/**
 * The meta level of a replay of a free run: instead of deciding, it asks each robot, in lock step,
 * for the requests its loop's record says it applied (or refused), at the cycles it says; so the
 * re-run applies the same requests at the same cycles and its robots do what they did, although the
 * meta level of the free run answered when its JVM let it. The kinds are the example's own.
 */
final class ReplayedMetaLevel implements MetaLevel {
  private final MetaLevel original;
  private final Map<String, Map<Long, List<Adaptation>>> script = new LinkedHashMap<>();

  /**
   * @param original the example's meta level, for its kinds and the robots it watched
   * @param loop the loop's record of the free run
   */
  ReplayedMetaLevel(MetaLevel original, List<Map<String, Object>> loop) {
    this.original = requireNonNull(original, "original");
    for (Map<String, Object> r : loop) {
      Object event = r.get("event");
      if (("applied".equals(event) || "refused".equals(event))
          && r.get("behavior") instanceof String behavior) {
        long cycle = ((Number) r.get("cycle")).longValue();
        script
            .computeIfAbsent(String.valueOf(r.get("robot")), k -> new LinkedHashMap<>())
            .computeIfAbsent(cycle, k -> new ArrayList<>())
            .add(new Adaptation.ApplyBehavior(behavior, r.get("input")));
      }
    }
  }

  @Override
  public Map<String, StructuralMeta<PState>> kinds(Kernel kernel) {
    return original.kinds(kernel);
  }

  @Override
  public List<Watch> watches(MetaNotes notes) {
    Set<String> robots = new LinkedHashSet<>();
    for (Watch w : original.watches(notes)) {
      robots.addAll(w.robots());
    }
    return List.of(new Watch(new Script(), List.copyOf(robots), ""));
  }

  @Override
  public List<Summary.Entry> figures() {
    return List.of(new Summary.Entry("meta level replayed", "from the loop's record"));
  }

  /**
   * Asks at the end of each robot's instant {@code n} (lock step, one instant behind) for what the
   * record says it applied in cycle {@code n}: an island's instant {@code n + 1} is the
   * simulation's cycle {@code n}, where that request is then applied.
   */
  private final class Script extends BMetaRobot {
    Script() {
      super("replayed-meta", Damping.none());
    }

    @Override
    public void onNotification(MetaContext context, Notification notification) {}

    @Override
    public void onInstant(MetaContext context, Address entity, long instant) {
      Map<Long, List<Adaptation>> byCycle = script.get(context.entity(entity).name());
      if (byCycle != null) {
        for (Adaptation request : byCycle.getOrDefault(instant, List.of())) {
          context.adapt(entity, request);
        }
      }
    }
  }
}

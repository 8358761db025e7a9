package org.armgals.maam;

import java.util.AbstractMap;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.jspecify.annotations.Nullable;

/**
 * {@link Scheduler#topological()}: numbers the modules by schema, then partial schedule, so that
 * the graph's smallest-number-first order breaks ties as the rules say.
 */
final class TopologicalScheduler implements Scheduler {

  static final TopologicalScheduler INSTANCE = new TopologicalScheduler();

  private TopologicalScheduler() {}

  @Override
  public Schedule schedule(List<Schema> schemas, List<Connector> connectors) {
    int size = 0;
    for (Schema schema : schemas) {
      size += schema.modules().size();
    }
    List<BehaviorModule> modules = new ArrayList<>(size);
    Map<String, Integer> index = HashMap.newHashMap(size);
    int[] schemaOf = new int[size];
    for (int s = 0; s < schemas.size(); s++) {
      for (BehaviorModule module : schemas.get(s).partialSchedule()) {
        Integer other = index.putIfAbsent(module.name(), modules.size());
        if (other != null) {
          throw new IllegalArgumentException(
              "module name '"
                  + module.name()
                  + "' in schemas '"
                  + schemas.get(schemaOf[other]).name()
                  + "' and '"
                  + schemas.get(s).name()
                  + "': expected unique in a robot");
        }
        schemaOf[modules.size()] = s;
        modules.add(module);
      }
    }
    Graph graph = new Graph(size);
    int base = 0;
    for (Schema schema : schemas) {
      int[] edges = ((SchemaImpl) schema).edges();
      for (int e = 0; e < edges.length; e += 2) {
        graph.edge(base + edges[e], base + edges[e + 1]);
      }
      base += schema.modules().size();
    }
    Map<PortRef, Derivator> derived = new HashMap<>();
    for (Connector connector : connectors) {
      check(connector, index, modules);
      if (connector instanceof Derivator derivator) {
        checkFedOnce(
            derivator, derived, schemas.get(schemaOf[index.get(derivator.target().module())]));
      }
      graph.edge(index.get(connector.source().module()), index.get(connector.target().module()));
    }
    int[] order = graph.order("the robot's program", i -> modules.get(i).name());
    BehaviorModule[] scheduled = new BehaviorModule[size];
    for (int i = 0; i < size; i++) {
      scheduled[i] = modules.get(order[i]);
    }
    return new Schedule(Arrays.asList(scheduled));
  }

  /** An input is fed by one wire or one derivator at most. */
  private static void checkFedOnce(
      Derivator derivator, Map<PortRef, Derivator> derived, Schema targetSchema) {
    Object other = derived.putIfAbsent(derivator.target(), derivator);
    if (other == null) {
      other = ((SchemaImpl) targetSchema).wireInto(derivator.target());
    }
    if (other != null) {
      throw new IllegalArgumentException(
          derivator
              + ": "
              + derivator.target()
              + " is already fed by "
              + other
              + ": expected at most one producer per input");
    }
  }

  private static void check(
      Connector connector, Map<String, Integer> index, List<BehaviorModule> all) {
    Map<String, BehaviorModule> modules = new ByName(index, all);
    String what = connector.toString();
    Ports.output(what, connector.source(), modules);
    switch (connector) {
      case Inhibitor inhibitor -> Ports.input(what, inhibitor.target(), modules);
      case Suppressor suppressor -> {
        Ports.output(what, suppressor.target(), modules);
        Ports.accepts(what, suppressor.source(), suppressor.target());
      }
      case Derivator derivator -> {
        Ports.input(what, derivator.target(), modules);
        Ports.accepts(what, derivator.source(), derivator.target());
      }
    }
  }

  /** The modules by name, as a map view over the index, for the checks of {@link Ports}. */
  private static final class ByName extends AbstractMap<String, BehaviorModule> {
    private final Map<String, Integer> index;
    private final List<BehaviorModule> modules;

    ByName(Map<String, Integer> index, List<BehaviorModule> modules) {
      this.index = index;
      this.modules = modules;
    }

    @Override
    public @Nullable BehaviorModule get(@Nullable Object name) {
      Integer at = index.get(name);
      return at == null ? null : modules.get(at);
    }

    @Override
    public int size() {
      return index.size();
    }

    @Override
    public java.util.Set<String> keySet() {
      return index.keySet();
    }

    @Override
    public java.util.Set<Map.Entry<String, BehaviorModule>> entrySet() {
      throw new UnsupportedOperationException("a view for look-ups");
    }
  }
}

package org.armgals.maam;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

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
    List<String> names = new ArrayList<>(size);
    Map<String, Integer> index = HashMap.newHashMap(size);
    Map<String, BehaviorModule> byName = HashMap.newHashMap(size);
    Map<String, String> schemaOf = HashMap.newHashMap(size);
    for (Schema schema : schemas) {
      for (BehaviorModule module : schema.partialSchedule()) {
        String other = schemaOf.putIfAbsent(module.name(), schema.name());
        if (other != null) {
          throw new IllegalArgumentException(
              "module name '"
                  + module.name()
                  + "' in schemas '"
                  + other
                  + "' and '"
                  + schema.name()
                  + "': expected unique in a robot");
        }
        index.put(module.name(), modules.size());
        byName.put(module.name(), module);
        modules.add(module);
        names.add(module.name());
      }
    }
    Graph graph = new Graph(size);
    for (Schema schema : schemas) {
      for (Wire wire : schema.wires()) {
        graph.edge(index.get(wire.from().module()), index.get(wire.to().module()));
      }
    }
    for (Connector connector : connectors) {
      check(connector, byName);
      graph.edge(index.get(connector.source().module()), index.get(connector.target().module()));
    }
    int[] order = graph.order("the robot's program", names);
    List<BehaviorModule> scheduled = new ArrayList<>(size);
    for (int i : order) {
      scheduled.add(modules.get(i));
    }
    return new Schedule(scheduled);
  }

  private static void check(Connector connector, Map<String, BehaviorModule> modules) {
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
}

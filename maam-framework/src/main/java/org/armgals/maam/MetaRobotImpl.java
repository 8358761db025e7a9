package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.jspecify.annotations.Nullable;

/** {@link MetaRobot}: computes the new program and its schedule before replacing the old one. */
final class MetaRobotImpl implements MetaRobot {

  private final Scheduler scheduler;
  private List<Schema> schemas = List.of();
  private List<Connector> connectors = List.of();
  private Schedule schedule = new Schedule(List.of());
  private long version;

  MetaRobotImpl(Scheduler scheduler) {
    this.scheduler = requireNonNull(scheduler, "scheduler");
  }

  @Override
  public List<Schema> schemas() {
    return schemas;
  }

  @Override
  public List<Connector> connectors() {
    return connectors;
  }

  @Override
  public Schedule schedule() {
    return schedule;
  }

  @Override
  public long version() {
    return version;
  }

  /**
   * Applies {@code adaptation}, or nothing at all if it fails.
   *
   * @throws IllegalArgumentException an unknown or duplicate name, a module change of another kind
   *     or other ports, a connector the scheduler refuses, or an input fed twice
   * @throws CycleException the program would have a cycle
   * @throws IllegalStateException a custom scheduler returned a schedule that breaks its contract
   *     (see {@link #checkSchedule})
   */
  void apply(ProgramChange.Change adaptation) {
    requireNonNull(adaptation, "adaptation");
    List<Schema> newSchemas = new ArrayList<>(schemas);
    List<Connector> newConnectors = new ArrayList<>(connectors);
    switch (adaptation) {
      case ProgramChange.SetScheduling set -> {
        newSchemas = new ArrayList<>(set.schemas());
        newConnectors = new ArrayList<>(set.connectors());
        checkUniqueSchemaNames(newSchemas);
      }
      case ProgramChange.AddSchema add -> {
        if (indexOf(add.schema().name()) >= 0) {
          throw new IllegalArgumentException(
              "schema name '" + add.schema().name() + "': already used");
        }
        newSchemas.add(add.schema());
      }
      case ProgramChange.RemoveSchema remove -> {
        int at = indexOf(remove.name());
        if (at < 0) {
          throw new IllegalArgumentException(
              "schema '" + remove.name() + "': expected one of " + schemaNames());
        }
        Schema removed = newSchemas.remove(at);
        Set<String> gone = new java.util.HashSet<>();
        removed.modules().forEach(module -> gone.add(module.name()));
        newConnectors.removeIf(
            c -> gone.contains(c.source().module()) || gone.contains(c.target().module()));
      }
      case ProgramChange.AddConnector add -> newConnectors.add(add.connector());
      case ProgramChange.RemoveConnector remove -> {
        if (!newConnectors.remove(remove.connector())) {
          throw new IllegalArgumentException(
              "connector " + remove.connector() + ": not in the program");
        }
      }
      case ProgramChange.ChangeModule change -> {
        changeModule(change.replacement());
        return;
      }
    }
    Schedule newSchedule = scheduler.schedule(newSchemas, newConnectors);
    if (scheduler != TopologicalScheduler.INSTANCE) {
      checkSchedule(newSchedule, newSchemas, newConnectors);
    }
    schemas = List.copyOf(newSchemas);
    connectors = List.copyOf(newConnectors);
    schedule = newSchedule;
    version++;
  }

  private void changeModule(BehaviorModule replacement) {
    for (int s = 0; s < schemas.size(); s++) {
      for (BehaviorModule module : schemas.get(s).modules()) {
        if (module.name().equals(replacement.name())) {
          checkSameShape(module, replacement);
          List<Schema> newSchemas = new ArrayList<>(schemas);
          newSchemas.set(s, ((SchemaImpl) schemas.get(s)).replace(replacement));
          List<BehaviorModule> order = new ArrayList<>(schedule.modules());
          order.replaceAll(m -> m.name().equals(replacement.name()) ? replacement : m);
          schemas = List.copyOf(newSchemas);
          schedule = new Schedule(order);
          version++;
          return;
        }
      }
    }
    throw new IllegalArgumentException(
        "change of module '" + replacement.name() + "': no module of that name in the program");
  }

  private static void checkSameShape(BehaviorModule old, BehaviorModule replacement) {
    if (kind(old) != kind(replacement)
        || !old.inputs().equals(replacement.inputs())
        || !old.outputs().equals(replacement.outputs())) {
      throw new IllegalArgumentException(
          "change of module '"
              + old.name()
              + "': expected a "
              + kind(old)
              + " with inputs "
              + old.inputs()
              + " and outputs "
              + old.outputs()
              + ", got a "
              + kind(replacement)
              + " with inputs "
              + replacement.inputs()
              + " and outputs "
              + replacement.outputs());
    }
  }

  private static String kind(BehaviorModule module) {
    return switch (module) {
      case Perceptor p -> "perceptor";
      case Reactor r -> "reactor";
      case Actuator a -> "actuator";
    };
  }

  /**
   * Checks what a custom scheduler returned against {@link Schedule}'s contract: every module of
   * the program once (the program's own instance), and the source of every wire and connector
   * before its target. A schedule that broke it would have a module read an input before its
   * producer wrote it this cycle, silently a cycle late. The built-in scheduler is not checked: its
   * property tests hold it to the contract.
   */
  private void checkSchedule(
      @Nullable Schedule s, List<Schema> schemas, List<Connector> connectors) {
    if (s == null) {
      throw new IllegalStateException(
          "scheduler " + scheduler + " returned null; expected a schedule of the program");
    }
    Map<String, BehaviorModule> program = new LinkedHashMap<>();
    for (Schema schema : schemas) {
      for (BehaviorModule module : schema.modules()) {
        program.put(module.name(), module);
      }
    }
    Map<String, Integer> position = new HashMap<>();
    List<BehaviorModule> order = s.modules();
    for (int i = 0; i < order.size(); i++) {
      BehaviorModule module = order.get(i);
      if (program.get(module.name()) != module) {
        throw badSchedule(s, "module '" + module.name() + "' is not one of the program's");
      }
      if (position.putIfAbsent(module.name(), i) != null) {
        throw badSchedule(s, "module '" + module.name() + "' is scheduled twice");
      }
    }
    if (position.size() != program.size()) {
      List<String> missing = new ArrayList<>(program.keySet());
      missing.removeAll(position.keySet());
      throw badSchedule(s, "modules " + missing + " are not scheduled");
    }
    for (Schema schema : schemas) {
      for (Wire wire : schema.wires()) {
        checkOrder(s, position, wire.from(), wire.to(), "wire " + wire);
      }
    }
    for (Connector connector : connectors) {
      checkOrder(s, position, connector.source(), connector.target(), "connector " + connector);
    }
  }

  private void checkOrder(
      Schedule s, Map<String, Integer> position, PortRef from, PortRef to, String edge) {
    Integer source = position.get(from.module());
    Integer target = position.get(to.module());
    if (source == null || target == null) {
      throw new IllegalArgumentException(edge + ": names a module that is not in the program");
    }
    if (source > target) {
      throw badSchedule(
          s, "'" + to.module() + "' runs before '" + from.module() + "', against the " + edge);
    }
  }

  private IllegalStateException badSchedule(Schedule s, String why) {
    return new IllegalStateException(
        "scheduler "
            + scheduler
            + " returned "
            + s.names()
            + ": "
            + why
            + "; expected every module of the program once, producers before consumers");
  }

  private static void checkUniqueSchemaNames(List<Schema> schemas) {
    Set<String> names = new java.util.HashSet<>();
    for (Schema schema : schemas) {
      if (!names.add(schema.name())) {
        throw new IllegalArgumentException("schema name '" + schema.name() + "': used twice");
      }
    }
  }

  private int indexOf(String schemaName) {
    for (int i = 0; i < schemas.size(); i++) {
      if (schemas.get(i).name().equals(schemaName)) {
        return i;
      }
    }
    return -1;
  }

  private List<String> schemaNames() {
    return schemas.stream().map(Schema::name).toList();
  }
}

package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

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

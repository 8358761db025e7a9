package org.armgals.maam;

import static java.util.Objects.requireNonNull;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.jspecify.annotations.Nullable;

/** {@link Schema}: checked and partially scheduled by its builder. */
final class SchemaImpl implements Schema {

  private final String name;
  private final List<ReactiveModule> reactiveModules;
  private final List<BehaviorModule> modules;
  private final List<Wire> wires;
  private final List<BehaviorModule> partialSchedule;
  private final int[] edges;
  private final Map<PortRef, Wire> fed;

  private SchemaImpl(String name, List<ReactiveModule> reactiveModules, List<Wire> wires) {
    this.name = name;
    this.reactiveModules = List.copyOf(reactiveModules);
    this.wires = List.copyOf(wires);
    Map<String, BehaviorModule> byName = new LinkedHashMap<>();
    Map<String, Integer> index = new HashMap<>();
    List<String> names = new ArrayList<>();
    for (ReactiveModule reactive : reactiveModules) {
      for (BehaviorModule module : reactive.modules()) {
        requireNonNull(module, "module");
        if (byName.putIfAbsent(module.name(), module) != null) {
          throw new IllegalArgumentException(
              "schema '" + name + "': module name '" + module.name() + "' used twice");
        }
        index.put(module.name(), names.size());
        names.add(module.name());
      }
    }
    if (byName.isEmpty()) {
      throw new IllegalArgumentException("schema '" + name + "' has no module: expected one");
    }
    this.modules = List.copyOf(byName.values());
    Graph graph = new Graph(modules.size());
    this.fed = new HashMap<>();
    String what = "schema '" + name + "'";
    for (Wire wire : wires) {
      Ports.output(what + ", wire " + wire, wire.from(), byName);
      Ports.input(what + ", wire " + wire, wire.to(), byName);
      Ports.accepts(what + ", wire " + wire, wire.from(), wire.to());
      Wire other = fed.putIfAbsent(wire.to(), wire);
      if (other != null) {
        throw new IllegalArgumentException(
            what
                + ": "
                + wire.to()
                + " fed twice, by "
                + other
                + " and "
                + wire
                + ": expected at most one wire into an input");
      }
      graph.edge(index.get(wire.from().module()), index.get(wire.to().module()));
    }
    int[] sorted = graph.order(what, names::get);
    int[] position = new int[sorted.length];
    List<BehaviorModule> order = new ArrayList<>(modules.size());
    for (int p = 0; p < sorted.length; p++) {
      order.add(modules.get(sorted[p]));
      position[sorted[p]] = p;
    }
    this.partialSchedule = List.copyOf(order);
    this.edges = new int[2 * wires.size()];
    for (int w = 0; w < wires.size(); w++) {
      edges[2 * w] = position[index.get(wires.get(w).from().module())];
      edges[2 * w + 1] = position[index.get(wires.get(w).to().module())];
    }
  }

  /** The wire into input {@code input}, if one of this schema's wires feeds it. */
  @Nullable Wire wireInto(PortRef input) {
    return fed.get(input);
  }

  /**
   * The wires as pairs of positions in the partial schedule, {@code [from0, to0, from1, to1, ...]}:
   * the scheduler merges schemas without looking names up.
   */
  int[] edges() {
    return edges;
  }

  /** This schema with {@code replacement} instead of the module of the same name. */
  SchemaImpl replace(BehaviorModule replacement) {
    List<ReactiveModule> reactives = new ArrayList<>();
    for (ReactiveModule reactive : reactiveModules) {
      List<BehaviorModule> members = new ArrayList<>();
      for (BehaviorModule module : reactive.modules()) {
        members.add(module.name().equals(replacement.name()) ? replacement : module);
      }
      reactives.add(new ReactiveModule(reactive.name(), members));
    }
    return new SchemaImpl(name, reactives, wires);
  }

  @Override
  public String name() {
    return name;
  }

  @Override
  public List<ReactiveModule> reactiveModules() {
    return reactiveModules;
  }

  @Override
  public List<BehaviorModule> modules() {
    return modules;
  }

  @Override
  public List<Wire> wires() {
    return wires;
  }

  @Override
  public List<BehaviorModule> partialSchedule() {
    return partialSchedule;
  }

  @Override
  public String toString() {
    return "Schema(" + name + ", " + modules.size() + " modules)";
  }

  /** {@link Schema.Builder}. */
  static final class BuilderImpl implements Schema.Builder {

    private final String name;
    private final List<ReactiveModule> reactiveModules = new ArrayList<>();
    private final List<Wire> wires = new ArrayList<>();

    BuilderImpl(String name) {
      requireNonNull(name, "name");
      if (name.isBlank()) {
        throw new IllegalArgumentException("schema name '" + name + "': expected not blank");
      }
      this.name = name;
    }

    @Override
    public Schema.Builder add(ReactiveModule module) {
      requireNonNull(module, "module");
      for (ReactiveModule other : reactiveModules) {
        if (other.name().equals(module.name())) {
          throw new IllegalArgumentException(
              "schema '" + name + "': reactive module name '" + module.name() + "' used twice");
        }
      }
      reactiveModules.add(module);
      return this;
    }

    @Override
    public Schema.Builder add(BehaviorModule module) {
      requireNonNull(module, "module");
      return add(ReactiveModule.of(module.name(), module));
    }

    @Override
    public <S extends Signal> Schema.Builder wire(
        BehaviorModule from, Port<? extends S> out, BehaviorModule to, Port<S> in) {
      wires.add(new Wire(PortRef.of(from, out), PortRef.of(to, in)));
      return this;
    }

    @Override
    public Schema build() {
      return new SchemaImpl(name, reactiveModules, wires);
    }
  }
}

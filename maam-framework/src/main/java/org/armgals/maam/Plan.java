package org.armgals.maam;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.armgals.maam.spi.Body;
import org.jspecify.annotations.Nullable;

/**
 * A robot's schedule compiled for running: modules in order, each output port a slot, each input
 * port the slot that feeds it, connectors as indexes. One cycle allocates nothing. A slot holds a
 * signal for the cycle whose number is its stamp, so nothing is cleared between cycles.
 *
 * <p>Threading: the robot's thread only. It is the {@link Inputs} and {@link Outputs} of the module
 * running, which it knows by {@link #current}.
 */
final class Plan implements Inputs, Outputs {

  /** Told of a module's failure. */
  interface Failures {
    void failed(BehaviorModule module, Exception error);
  }

  private static final int UNFED = -1;

  private final BehaviorModule[] modules;
  private final Port<?>[][] inPorts;
  private final int[][] inSlots;
  private final Gate[][] @Nullable [] inGates;
  private final Port<?>[][] outPorts;
  private final int[][] outSlots;
  private final Watch[][] watches;
  private final Replace[][] replaces;
  private final PortRef[] slotRefs;
  private final @Nullable Signal[] values;
  private final long[] stamps;

  private int current;
  private long cycle;
  private long now;

  Plan(Schedule schedule, List<Schema> schemas, List<Connector> connectors, StateOf states) {
    List<BehaviorModule> order = schedule.modules();
    int n = order.size();
    modules = order.toArray(new BehaviorModule[0]);
    Map<String, Integer> moduleIndex = HashMap.newHashMap(n);
    Map<PortRef, Integer> slotOf = new HashMap<>();
    List<PortRef> refs = new ArrayList<>();
    outPorts = new Port<?>[n][];
    outSlots = new int[n][];
    inPorts = new Port<?>[n][];
    inSlots = new int[n][];
    inGates = new Gate[n][][];
    for (int i = 0; i < n; i++) {
      BehaviorModule module = modules[i];
      moduleIndex.put(module.name(), i);
      outPorts[i] = module.outputs().toArray(new Port<?>[0]);
      outSlots[i] = new int[outPorts[i].length];
      for (int j = 0; j < outPorts[i].length; j++) {
        PortRef ref = new PortRef(module.name(), outPorts[i][j]);
        outSlots[i][j] = refs.size();
        slotOf.put(ref, refs.size());
        refs.add(ref);
      }
      inPorts[i] = module.inputs().toArray(new Port<?>[0]);
      inSlots[i] = new int[inPorts[i].length];
      java.util.Arrays.fill(inSlots[i], UNFED);
      inGates[i] = new Gate[inPorts[i].length][];
    }
    slotRefs = refs.toArray(new PortRef[0]);
    values = new Signal[slotRefs.length];
    stamps = new long[slotRefs.length];
    for (Schema schema : schemas) {
      for (Wire wire : schema.wires()) {
        feed(moduleIndex, slotOf, wire.from(), wire.to());
      }
    }
    List<List<Watch>> watchLists = lists(n);
    List<List<Replace>> replaceLists = lists(n);
    List<List<List<Gate>>> gateLists = new ArrayList<>(n);
    for (int i = 0; i < n; i++) {
      gateLists.add(lists(inPorts[i].length));
    }
    for (Connector connector : connectors) {
      int source = moduleIndex.get(connector.source().module());
      int sourceSlot = slotOf.get(connector.source());
      int target = moduleIndex.get(connector.target().module());
      switch (connector) {
        case Derivator derivator ->
            feed(moduleIndex, slotOf, derivator.source(), derivator.target());
        case Inhibitor inhibitor -> {
          ConnectorState state = states.of(inhibitor);
          watchLists.get(source).add(new Watch(sourceSlot, state));
          int input = indexOf(inPorts[target], inhibitor.target().port());
          gateLists.get(target).get(input).add(new Gate(state, inhibitor.hold().toNanos()));
        }
        case Suppressor suppressor -> {
          ConnectorState state = states.of(suppressor);
          watchLists.get(source).add(new Watch(sourceSlot, state));
          replaceLists
              .get(target)
              .add(
                  new Replace(slotOf.get(suppressor.target()), state, suppressor.hold().toNanos()));
        }
      }
    }
    watches = new Watch[n][];
    replaces = new Replace[n][];
    for (int i = 0; i < n; i++) {
      watches[i] = watchLists.get(i).toArray(new Watch[0]);
      replaces[i] = replaceLists.get(i).toArray(new Replace[0]);
      for (int j = 0; j < inPorts[i].length; j++) {
        List<Gate> gates = gateLists.get(i).get(j);
        inGates[i][j] = gates.isEmpty() ? null : gates.toArray(new Gate[0]);
      }
    }
  }

  /** Where a robot finds the state of a connector, kept across plans. */
  interface StateOf {
    ConnectorState of(Connector connector);
  }

  /** Runs every module once, in order, as cycle {@code cycle} at time {@code now}. */
  void run(long cycle, long now, Body body, Failures failures) {
    this.cycle = cycle;
    this.now = now;
    for (int i = 0; i < modules.length; i++) {
      current = i;
      BehaviorModule module = modules[i];
      try {
        switch (module) {
          case Perceptor perceptor -> perceptor.perceive(body, this);
          case Reactor reactor -> reactor.react(this, this);
          case Actuator actuator -> actuator.act(this, body);
        }
      } catch (Exception e) {
        for (int slot : outSlots[i]) {
          stamps[slot] = 0;
        }
        failures.failed(module, e);
      }
      for (Watch watch : watches[i]) {
        if (stamps[watch.slot] == cycle) {
          watch.state.lastActive = now;
          watch.state.latched = values[watch.slot];
        }
      }
      for (Replace replace : replaces[i]) {
        if (replace.state.holds(now, replace.holdNanos)) {
          values[replace.slot] = replace.state.latched;
          stamps[replace.slot] = cycle;
        }
      }
    }
  }

  /** What was emitted in the last cycle run, after suppression. */
  List<CycleReport.Emission> emissions() {
    List<CycleReport.Emission> emitted = new ArrayList<>();
    for (int slot = 0; slot < stamps.length; slot++) {
      Signal value = values[slot];
      if (stamps[slot] == cycle && value != null) {
        emitted.add(new CycleReport.Emission(slotRefs[slot], value));
      }
    }
    return emitted;
  }

  /** Replaces the module of the same name; the caller checked its kind and ports. */
  void replace(BehaviorModule replacement) {
    for (int i = 0; i < modules.length; i++) {
      if (modules[i].name().equals(replacement.name())) {
        modules[i] = replacement;
      }
    }
  }

  @Override
  @SuppressWarnings("unchecked") // the wiring was type-checked against the ports' types
  public <S extends Signal> @Nullable S get(Port<S> port) {
    Port<?>[] ports = inPorts[current];
    for (int j = 0; j < ports.length; j++) {
      if (ports[j] == port || ports[j].equals(port)) {
        Gate[] gates = inGates[current][j];
        if (gates != null) {
          for (Gate gate : gates) {
            if (gate.state.holds(now, gate.holdNanos)) {
              return null;
            }
          }
        }
        int slot = inSlots[current][j];
        return slot == UNFED || stamps[slot] != cycle ? null : (S) values[slot];
      }
    }
    throw new IllegalArgumentException(
        "input "
            + port
            + " of module '"
            + modules[current].name()
            + "': expected one of "
            + modules[current].inputs());
  }

  @Override
  public <S extends Signal> void emit(Port<S> port, S signal) {
    Port<?>[] ports = outPorts[current];
    for (int j = 0; j < ports.length; j++) {
      if (ports[j] == port || ports[j].equals(port)) {
        if (!port.type().isInstance(signal)) {
          throw new IllegalArgumentException(
              "output "
                  + port
                  + " of module '"
                  + modules[current].name()
                  + "' takes "
                  + port.type().getName()
                  + ", got "
                  + (signal == null ? "null" : signal.getClass().getName()));
        }
        int slot = outSlots[current][j];
        values[slot] = signal;
        stamps[slot] = cycle;
        return;
      }
    }
    throw new IllegalArgumentException(
        "output "
            + port
            + " of module '"
            + modules[current].name()
            + "': expected one of "
            + modules[current].outputs());
  }

  private void feed(
      Map<String, Integer> moduleIndex, Map<PortRef, Integer> slotOf, PortRef from, PortRef to) {
    int target = moduleIndex.get(to.module());
    inSlots[target][indexOf(inPorts[target], to.port())] = slotOf.get(from);
  }

  private static int indexOf(Port<?>[] ports, Port<?> port) {
    for (int j = 0; j < ports.length; j++) {
      if (ports[j].equals(port)) {
        return j;
      }
    }
    throw new IllegalStateException("port " + port + " not in " + java.util.Arrays.toString(ports));
  }

  private static <T> List<List<T>> lists(int n) {
    List<List<T>> lists = new ArrayList<>(n);
    for (int i = 0; i < n; i++) {
      lists.add(new ArrayList<>());
    }
    return lists;
  }

  /** After its source module ran, marks a connector active if the source emitted. */
  private record Watch(int slot, ConnectorState state) {}

  /** An inhibitor's hold on an input. */
  private record Gate(ConnectorState state, long holdNanos) {}

  /** After its target module ran, a suppressor's replacement of an output. */
  private record Replace(int slot, ConnectorState state, long holdNanos) {}
}

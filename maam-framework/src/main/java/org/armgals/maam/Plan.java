package org.armgals.maam;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.armgals.maam.spi.Body;
import org.jspecify.annotations.Nullable;

/**
 * A robot's schedule compiled for running: a {@link Step} per module in order, each output port a
 * slot, each input port the slot that feeds it, connectors as indexes. One cycle allocates nothing.
 * A slot holds a signal for the cycle whose number is its stamp, so nothing is cleared between
 * cycles.
 *
 * <p>Threading: the robot's thread only. Each module's {@link Step} is its {@link Inputs} and
 * {@link Outputs}: handing a module its own step, rather than noting which module runs in a field
 * the plan's reads and emissions look up, spares a cycle a reference store per module.
 */
final class Plan {

  /** Told of a module's failure. */
  interface Failures {
    void failed(BehaviorModule module, Exception error);
  }

  /** Where a robot finds the state of a connector, kept across plans. */
  interface StateOf {
    ConnectorState of(Connector connector);
  }

  private static final int UNFED = -1;
  private static final int PERCEPTOR = 0;
  private static final int REACTOR = 1;
  private static final int ACTUATOR = 2;

  private final Step[] steps;
  private final PortRef[] slotRefs;
  private final @Nullable Signal[] values;
  private final long[] stamps;

  private long cycle;
  private long now;

  Plan(Schedule schedule, List<Schema> schemas, List<Connector> connectors, StateOf states) {
    List<BehaviorModule> order = schedule.modules();
    int n = order.size();
    steps = new Step[n];
    Map<String, Step> byName = HashMap.newHashMap(n);
    Map<PortRef, Integer> slotOf = new HashMap<>();
    List<PortRef> refs = new ArrayList<>();
    for (int i = 0; i < n; i++) {
      BehaviorModule module = order.get(i);
      Step step =
          new Step(
              module,
              module.inputs().toArray(new Port<?>[0]),
              module.outputs().toArray(new Port<?>[0]));
      for (int j = 0; j < step.outPorts.length; j++) {
        PortRef ref = new PortRef(module.name(), step.outPorts[j]);
        step.outSlots[j] = refs.size();
        slotOf.put(ref, refs.size());
        refs.add(ref);
      }
      steps[i] = step;
      byName.put(module.name(), step);
    }
    slotRefs = refs.toArray(new PortRef[0]);
    values = new Signal[slotRefs.length];
    stamps = new long[slotRefs.length];
    for (Schema schema : schemas) {
      for (Wire wire : schema.wires()) {
        byName.get(wire.to().module()).feed(wire.to().port(), slotOf.get(wire.from()));
      }
    }
    for (Connector connector : connectors) {
      Step source = byName.get(connector.source().module());
      int sourceSlot = slotOf.get(connector.source());
      Step target = byName.get(connector.target().module());
      switch (connector) {
        case Derivator derivator -> target.feed(derivator.target().port(), sourceSlot);
        case Inhibitor inhibitor -> {
          ConnectorState state = states.of(inhibitor);
          source.watches = append(source.watches, new Watch(sourceSlot, state));
          source.connected = true;
          target.gated = true;
          int input = target.input(inhibitor.target().port());
          Gate[] gates = target.inGates[input];
          Gate gate = new Gate(state, inhibitor.hold().toNanos());
          target.inGates[input] = gates == null ? new Gate[] {gate} : append(gates, gate);
        }
        case Suppressor suppressor -> {
          ConnectorState state = states.of(suppressor);
          source.watches = append(source.watches, new Watch(sourceSlot, state));
          source.connected = true;
          target.connected = true;
          target.replaces =
              append(
                  target.replaces,
                  new Replace(slotOf.get(suppressor.target()), state, suppressor.hold().toNanos()));
        }
      }
    }
  }

  /** Runs every module once, in order, as cycle {@code cycle} at time {@code now}. */
  void run(long cycle, long now, Body body, Failures failures) {
    this.cycle = cycle;
    this.now = now;
    for (Step step : steps) {
      BehaviorModule module = step.module;
      try {
        // An int switch with casts: cheaper per step than a pattern switch over the kinds.
        switch (step.kind) {
          case PERCEPTOR -> ((Perceptor) module).perceive(body, step);
          case REACTOR -> ((Reactor) module).react(step, step);
          default -> ((Actuator) module).act(step, body);
        }
      } catch (Exception e) {
        for (int slot : step.outSlots) {
          stamps[slot] = 0;
        }
        failures.failed(module, e);
      }
      if (step.connected) {
        connectors(step, cycle, now);
      }
    }
  }

  /** After {@code step}'s module ran: the connectors it is the source or the target of. */
  private void connectors(Step step, long cycle, long now) {
    for (Watch watch : step.watches) {
      if (stamps[watch.slot] == cycle) {
        watch.state.lastActive = now;
        watch.state.latched = values[watch.slot];
      }
    }
    for (Replace replace : step.replaces) {
      if (replace.state.holds(now, replace.holdNanos)) {
        values[replace.slot] = replace.state.latched;
        stamps[replace.slot] = cycle;
      }
    }
  }

  /** What was emitted in the last cycle run, after suppression. */
  List<Emission> emissions() {
    List<Emission> emitted = new ArrayList<>();
    for (int slot = 0; slot < stamps.length; slot++) {
      Signal value = values[slot];
      if (stamps[slot] == cycle && value != null) {
        emitted.add(new Emission(slotRefs[slot], value));
      }
    }
    return emitted;
  }

  /** Replaces the module of the same name; the caller checked its kind and ports. */
  void replace(BehaviorModule replacement) {
    for (Step step : steps) {
      if (step.module.name().equals(replacement.name())) {
        step.module = replacement;
      }
    }
  }

  private static <T> T[] append(T[] array, T element) {
    T[] longer = Arrays.copyOf(array, array.length + 1);
    longer[array.length] = element;
    return longer;
  }

  /**
   * One module's place in the plan: its ports, their slots, the connectors around it; the module's
   * {@link Inputs} and {@link Outputs} while it runs.
   */
  private final class Step implements Inputs, Outputs {
    BehaviorModule module;
    final int kind;
    final Port<?>[] inPorts;
    final int[] inSlots;
    final Gate[] @Nullable [] inGates;
    final Port<?>[] outPorts;
    final int[] outSlots;
    Watch[] watches = new Watch[0];
    Replace[] replaces = new Replace[0];

    /** Whether a connector watches this module's outputs or replaces one: run after it. */
    boolean connected;

    /** Whether an inhibitor gates one of this module's inputs. */
    boolean gated;

    /** The first two input ports and their slots, the first output port (null if none). */
    final @Nullable Port<?> in0;

    final @Nullable Port<?> in1;
    int slot0 = UNFED;
    int slot1 = UNFED;
    final @Nullable Port<?> out0;

    Step(BehaviorModule module, Port<?>[] inPorts, Port<?>[] outPorts) {
      this.module = module;
      this.kind =
          switch (module) {
            case Perceptor p -> PERCEPTOR;
            case Reactor r -> REACTOR;
            case Actuator a -> ACTUATOR;
          };
      this.inPorts = inPorts;
      this.inSlots = new int[inPorts.length];
      Arrays.fill(inSlots, UNFED);
      this.inGates = new Gate[inPorts.length][];
      this.outPorts = outPorts;
      this.outSlots = new int[outPorts.length];
      this.in0 = inPorts.length > 0 ? inPorts[0] : null;
      this.in1 = inPorts.length > 1 ? inPorts[1] : null;
      this.out0 = outPorts.length > 0 ? outPorts[0] : null;
    }

    String name() {
      return module.name();
    }

    @Override
    @SuppressWarnings("unchecked") // the wiring was type-checked against the ports' types
    public <S extends Signal> @Nullable S get(Port<S> port) {
      int slot;
      int j;
      if (port == in0) {
        j = 0; // the first two inputs, as most modules have at most two: no search
        slot = slot0;
      } else if (port == in1) {
        j = 1;
        slot = slot1;
      } else {
        j = input(port);
        slot = inSlots[j];
      }
      if (slot == UNFED) {
        return null; // nothing feeds it: nothing to read, whatever gates it
      }
      if (gated) {
        Gate[] gates = inGates[j];
        if (gates != null) {
          for (Gate gate : gates) {
            if (gate.state.holds(now, gate.holdNanos)) {
              return null;
            }
          }
        }
      }
      return stamps[slot] != cycle ? null : (S) values[slot];
    }

    @Override
    public <S extends Signal> void emit(Port<S> port, S signal) {
      int j = port == out0 ? 0 : output(port);
      if (!port.type().isInstance(signal)) {
        throw new IllegalArgumentException(
            "output "
                + port
                + " of module '"
                + name()
                + "' takes "
                + port.type().getName()
                + ", got "
                + (signal == null ? "null" : signal.getClass().getName()));
      }
      int slot = outSlots[j];
      values[slot] = signal;
      stamps[slot] = cycle;
    }

    void feed(Port<?> port, int slot) {
      int j = input(port);
      inSlots[j] = slot;
      if (j == 0) {
        slot0 = slot;
      } else if (j == 1) {
        slot1 = slot;
      }
    }

    /** The index of input {@code port}: by identity first, as modules pass their constants. */
    int input(Port<?> port) {
      Port<?>[] ports = inPorts;
      for (int j = 0; j < ports.length; j++) {
        if (ports[j] == port) {
          return j;
        }
      }
      for (int j = 0; j < ports.length; j++) {
        if (ports[j].equals(port)) {
          return j;
        }
      }
      throw new IllegalArgumentException(
          "input " + port + " of module '" + name() + "': expected one of " + List.of(inPorts));
    }

    int output(Port<?> port) {
      Port<?>[] ports = outPorts;
      for (int j = 0; j < ports.length; j++) {
        if (ports[j] == port) {
          return j;
        }
      }
      for (int j = 0; j < ports.length; j++) {
        if (ports[j].equals(port)) {
          return j;
        }
      }
      throw new IllegalArgumentException(
          "output " + port + " of module '" + name() + "': expected one of " + List.of(outPorts));
    }
  }

  /** After its source module ran, marks a connector active if the source emitted. */
  private record Watch(int slot, ConnectorState state) {}

  /** An inhibitor's hold on an input. */
  private record Gate(ConnectorState state, long holdNanos) {}

  /** After its target module ran, a suppressor's replacement of an output. */
  private record Replace(int slot, ConnectorState state, long holdNanos) {}
}

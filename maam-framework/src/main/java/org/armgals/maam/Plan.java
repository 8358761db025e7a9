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
 * {@link Cell}, each input port the cell that feeds it, connectors as references to those cells.
 * One cycle allocates nothing. The cells are emptied at the start of each cycle, so a cell holds
 * what its port emitted in the current cycle, or nothing.
 *
 * <p>Threading: the robot's thread only. Each module's {@link Step} is its {@link Inputs} and
 * {@link Outputs}: handing a module its own step, rather than noting which module runs in a field
 * the plan's reads and emissions look up, spares a cycle a reference store per module. A read of
 * one of a module's first two inputs and an emission on its first output are a comparison and a
 * field access, as in a hand-written loop (decision 0074); everything else (other ports, inhibited
 * inputs, errors) goes to methods of its own that the compiler leaves out of line.
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

  private static final int PERCEPTOR = 0;
  private static final int REACTOR = 1;
  private static final int ACTUATOR = 2;

  /**
   * Stands for "no fast path" in a step's first two inputs and first output: a port no module
   * passes, so the comparison fails and the read or emission takes the slow path.
   */
  private static final Port<Signal> NONE = Port.of("none", Signal.class);

  private final Step[] steps;
  private final PortRef[] cellRefs;
  private final Cell[] cells;

  /** What an input nothing feeds reads: a cell no module emits on, always empty. */
  private final Cell unfed = new Cell();

  private long now;

  Plan(Schedule schedule, List<Schema> schemas, List<Connector> connectors, StateOf states) {
    List<BehaviorModule> order = schedule.modules();
    int n = order.size();
    steps = new Step[n];
    Map<String, Step> byName = HashMap.newHashMap(n);
    Map<PortRef, Cell> cellOf = new HashMap<>();
    List<PortRef> refs = new ArrayList<>();
    List<Cell> all = new ArrayList<>();
    for (int i = 0; i < n; i++) {
      BehaviorModule module = order.get(i);
      Step step =
          new Step(
              module,
              module.inputs().toArray(new Port<?>[0]),
              module.outputs().toArray(new Port<?>[0]));
      for (int j = 0; j < step.outPorts.length; j++) {
        PortRef ref = new PortRef(module.name(), step.outPorts[j]);
        Cell cell = new Cell();
        step.outCells[j] = cell;
        cellOf.put(ref, cell);
        refs.add(ref);
        all.add(cell);
      }
      steps[i] = step;
      byName.put(module.name(), step);
    }
    cellRefs = refs.toArray(new PortRef[0]);
    cells = all.toArray(new Cell[0]);
    for (Schema schema : schemas) {
      for (Wire wire : schema.wires()) {
        byName.get(wire.to().module()).feed(wire.to().port(), cellOf.get(wire.from()));
      }
    }
    for (Connector connector : connectors) {
      Step source = byName.get(connector.source().module());
      Cell sourceCell = cellOf.get(connector.source());
      Step target = byName.get(connector.target().module());
      switch (connector) {
        case Derivator derivator -> target.feed(derivator.target().port(), sourceCell);
        case Inhibitor inhibitor -> {
          ConnectorState state = states.of(inhibitor);
          source.watches = append(source.watches, new Watch(sourceCell, state));
          source.connected = true;
          int input = target.input(inhibitor.target().port());
          Gate[] gates = target.inGates[input];
          Gate gate = new Gate(state, inhibitor.hold().toNanos());
          target.inGates[input] = gates == null ? new Gate[] {gate} : append(gates, gate);
        }
        case Suppressor suppressor -> {
          ConnectorState state = states.of(suppressor);
          source.watches = append(source.watches, new Watch(sourceCell, state));
          source.connected = true;
          target.connected = true;
          target.replaces =
              append(
                  target.replaces,
                  new Replace(cellOf.get(suppressor.target()), state, suppressor.hold().toNanos()));
        }
      }
    }
    for (Step step : steps) {
      step.seal();
    }
  }

  /** Runs every module once, in order, at time {@code now}. */
  void run(long now, Body body, Failures failures) {
    this.now = now;
    for (Cell cell : cells) {
      cell.value = null;
    }
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
        for (Cell cell : step.outCells) {
          cell.value = null;
        }
        failures.failed(module, e);
      }
      if (step.connected) {
        connectors(step, now);
      }
    }
  }

  /** After {@code step}'s module ran: the connectors it is the source or the target of. */
  private static void connectors(Step step, long now) {
    for (Watch watch : step.watches) {
      Signal value = watch.cell.value;
      if (value != null) {
        watch.state.lastActive = now;
        watch.state.latched = value;
      }
    }
    for (Replace replace : step.replaces) {
      if (replace.state.holds(now, replace.holdNanos)) {
        replace.cell.value = replace.state.latched;
      }
    }
  }

  /** What was emitted in the last cycle run, after suppression. */
  List<Emission> emissions() {
    List<Emission> emitted = new ArrayList<>();
    for (int i = 0; i < cells.length; i++) {
      Signal value = cells[i].value;
      if (value != null) {
        emitted.add(new Emission(cellRefs[i], value));
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
   * What one output port emitted this cycle, or null. An object of its own rather than an element
   * of an array of signals: a store into a field needs no array store check.
   */
  private static final class Cell {
    @Nullable Signal value;
  }

  /**
   * One module's place in the plan: its ports, their cells, the connectors around it; the module's
   * {@link Inputs} and {@link Outputs} while it runs.
   */
  private final class Step implements Inputs, Outputs {
    BehaviorModule module;
    final int kind;
    final Port<?>[] inPorts;
    final Cell[] inCells;
    final Gate[] @Nullable [] inGates;
    final Port<?>[] outPorts;
    final Cell[] outCells;
    Watch[] watches = new Watch[0];
    Replace[] replaces = new Replace[0];

    /** Whether a connector watches this module's outputs or replaces one: run after it. */
    boolean connected;

    /**
     * The fast paths, set by {@link #seal}: the first two inputs when no inhibitor gates them, the
     * first output, and their cells; {@link #NONE} where there is no fast path.
     */
    Port<?> in0 = NONE;

    Port<?> in1 = NONE;
    Port<?> out0 = NONE;
    Cell cell0;
    Cell cell1;
    Cell outCell0;

    Step(BehaviorModule module, Port<?>[] inPorts, Port<?>[] outPorts) {
      this.module = module;
      this.kind =
          switch (module) {
            case Perceptor p -> PERCEPTOR;
            case Reactor r -> REACTOR;
            case Actuator a -> ACTUATOR;
          };
      this.inPorts = inPorts;
      this.inCells = new Cell[inPorts.length];
      Arrays.fill(inCells, unfed);
      this.inGates = new Gate[inPorts.length][];
      this.outPorts = outPorts;
      this.outCells = new Cell[outPorts.length];
      this.cell0 = unfed;
      this.cell1 = unfed;
      this.outCell0 = unfed;
    }

    String name() {
      return module.name();
    }

    /** Once the wires and connectors are in: the fast paths. */
    void seal() {
      if (inPorts.length > 0 && inGates[0] == null) {
        in0 = inPorts[0];
        cell0 = inCells[0];
      }
      if (inPorts.length > 1 && inGates[1] == null) {
        in1 = inPorts[1];
        cell1 = inCells[1];
      }
      if (outPorts.length > 0) {
        out0 = outPorts[0];
        outCell0 = outCells[0];
      }
    }

    @Override
    @SuppressWarnings("unchecked") // the wiring was type-checked against the ports' types
    public <S extends Signal> @Nullable S get(Port<S> port) {
      if (port == in0) {
        return (S) cell0.value;
      }
      if (port == in1) {
        return (S) cell1.value;
      }
      return (S) read(port);
    }

    /** A read off the fast path: a later input, one an inhibitor gates, or not an input. */
    private @Nullable Signal read(Port<?> port) {
      int j = input(port);
      Cell cell = inCells[j];
      if (cell == unfed) {
        return null; // nothing feeds it: nothing to read, whatever gates it
      }
      Gate[] gates = inGates[j];
      if (gates != null) {
        for (Gate gate : gates) {
          if (gate.state.holds(now, gate.holdNanos)) {
            return null;
          }
        }
      }
      return cell.value;
    }

    @Override
    public <S extends Signal> void emit(Port<S> port, S signal) {
      if (port == out0 && port.type().isInstance(signal)) {
        outCell0.value = signal;
      } else {
        write(port, signal);
      }
    }

    /** An emission off the fast path: a later output, or an error. */
    private void write(Port<?> port, @Nullable Signal signal) {
      int j = output(port);
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
      outCells[j].value = signal;
    }

    void feed(Port<?> port, Cell cell) {
      inCells[input(port)] = cell;
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
  private record Watch(Cell cell, ConnectorState state) {}

  /** An inhibitor's hold on an input. */
  private record Gate(ConnectorState state, long holdNanos) {}

  /** After its target module ran, a suppressor's replacement of an output. */
  private record Replace(Cell cell, ConnectorState state, long holdNanos) {}
}

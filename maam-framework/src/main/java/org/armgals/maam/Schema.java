package org.armgals.maam;

import java.util.List;

/**
 * A logical function of a robot (paper §5.4): reactive modules of behavior modules, wired into a
 * DAG. A schema is immutable and is checked when built: unique module names, wires between ports of
 * its own modules with compatible types, at most one wire into an input, no cycle. It carries its
 * partial schedule, computed once: the {@link Scheduler} merges partial schedules into a robot's.
 */
public sealed interface Schema permits SchemaImpl {

  /** A builder of a schema named {@code name} (unique in a robot). */
  static Builder builder(String name) {
    return new SchemaImpl.BuilderImpl(name);
  }

  /** Its name, unique in a robot. */
  String name();

  /** Its reactive modules, in declaration order. */
  List<ReactiveModule> reactiveModules();

  /** Its behavior modules, in declaration order. */
  List<BehaviorModule> modules();

  /** Its wires, in declaration order. */
  List<Wire> wires();

  /**
   * Its modules in a topological order of its wires, ties broken by declaration order: the order
   * they keep in the robot's schedule unless connectors to other schemas say otherwise.
   */
  List<BehaviorModule> partialSchedule();

  /** Declares a schema. Not thread-safe. */
  interface Builder {

    /** Adds a reactive module. */
    Builder add(ReactiveModule module);

    /** Adds a behavior module alone in a reactive module of the same name. */
    Builder add(BehaviorModule module);

    /** Wires output {@code out} of {@code from} to input {@code in} of {@code to}. */
    <S extends Signal> Builder wire(
        BehaviorModule from, Port<? extends S> out, BehaviorModule to, Port<S> in);

    /**
     * The schema, checked.
     *
     * @throws IllegalArgumentException a duplicate name, a wire to a port or module not in the
     *     schema, incompatible types, or two wires into one input
     * @throws CycleException its wires make a cycle
     */
    Schema build();
  }
}

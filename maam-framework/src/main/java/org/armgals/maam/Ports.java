package org.armgals.maam;

import java.util.Map;

/** The checks of port references against the modules they name, shared by schemas and robots. */
final class Ports {

  private Ports() {}

  /** The output port {@code ref}, checked to be one of its module's outputs. */
  static Port<?> output(String what, PortRef ref, Map<String, BehaviorModule> modules) {
    BehaviorModule module = module(what, ref, modules);
    if (!module.outputs().contains(ref.port())) {
      throw new IllegalArgumentException(
          what
              + ": "
              + ref
              + " is not an output of '"
              + module.name()
              + "': expected one of "
              + module.outputs());
    }
    return ref.port();
  }

  /** The input port {@code ref}, checked to be one of its module's inputs. */
  static Port<?> input(String what, PortRef ref, Map<String, BehaviorModule> modules) {
    BehaviorModule module = module(what, ref, modules);
    if (!module.inputs().contains(ref.port())) {
      throw new IllegalArgumentException(
          what
              + ": "
              + ref
              + " is not an input of '"
              + module.name()
              + "': expected one of "
              + module.inputs());
    }
    return ref.port();
  }

  /** Checks that what {@code from} carries may be read as what {@code to} carries. */
  static void accepts(String what, PortRef from, PortRef to) {
    if (!to.port().type().isAssignableFrom(from.port().type())) {
      throw new IllegalArgumentException(
          what
              + ": "
              + to
              + " takes "
              + to.port().type().getName()
              + ", "
              + from
              + " carries "
              + from.port().type().getName());
    }
  }

  private static BehaviorModule module(
      String what, PortRef ref, Map<String, BehaviorModule> modules) {
    BehaviorModule module = modules.get(ref.module());
    if (module == null) {
      throw new IllegalArgumentException(
          what
              + ": no module named '"
              + ref.module()
              + "': expected one of "
              + (modules.size() <= 20 ? modules.keySet() : "its " + modules.size() + " modules"));
    }
    return module;
  }
}

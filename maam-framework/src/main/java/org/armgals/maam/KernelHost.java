package org.armgals.maam;

import org.armgals.kernel.Adaptation;
import org.armgals.kernel.spi.InstantContext;
import org.armgals.kernel.spi.ReactiveProgram;

/**
 * Runs a robot as a kernel entity (paper figure 8): the robot's cycle is the entity's program, and
 * the kernel's adaptation requests for it are applied to its program at the entity's adaptation
 * point. The one class that knows how a robot sits in the kernel.
 */
final class KernelHost implements ReactiveProgram {
  private final AbstractRobot robot;

  KernelHost(AbstractRobot robot) {
    this.robot = robot;
  }

  @Override
  public void react(InstantContext instant) {
    robot.kernelCycle(instant);
  }

  @Override
  public void adapt(Adaptation adaptation) {
    switch (adaptation) {
      case Adaptation.ApplyBehavior a -> {
        if (a.behavior().equals(RobotAdaptations.CHANGE_MODULE)
            && a.input() instanceof java.util.Map<?, ?> byName) {
          robot.applyOrRefuse(new org.armgals.maam.Adaptation.ChangeModule(fromCatalog(byName)));
          return;
        }
        if (!(a.input() instanceof org.armgals.maam.Adaptation change)) {
          throw new IllegalArgumentException(
              "robot "
                  + robot.name()
                  + " cannot apply "
                  + a.behavior()
                  + " with "
                  + a.input()
                  + "; expected a program change (RobotKind.request)");
        }
        if (!RobotAdaptations.name(change).equals(a.behavior())) {
          throw new IllegalArgumentException(
              "behavior " + a.behavior() + " does not match the change " + change);
        }
        robot.applyOrRefuse(change);
      }
      case Adaptation.SetNotification s -> {}
    }
  }

  /** The module a {@link RobotKind#changeModule(String, java.util.Map)} request names. */
  private BehaviorModule fromCatalog(java.util.Map<?, ?> request) {
    if (!(request.get(RobotKind.MODULE) instanceof String name)
        || !(request.get(RobotKind.PARAMETERS) instanceof java.util.Map<?, ?> raw)) {
      throw new IllegalArgumentException(
          "robot "
              + robot.name()
              + " cannot change a module from "
              + request
              + "; expected {module: name, parameters: {...}}");
    }
    java.util.Map<String, Object> parameters = new java.util.LinkedHashMap<>();
    raw.forEach((k, v) -> parameters.put(String.valueOf(k), v));
    return robot.module(name, parameters);
  }
}
